// SPDX-License-Identifier: MIT
// modules/hud on GL: the same overlay as the soft backend draws. Panels copy exactly; text
// panels blend a translucent box, which may round one code differently.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "hud/text_layout.hpp"
#include "hud_scene.hpp"

namespace hud {
namespace {

using testing::kH;
using testing::kW;

TEST(HudOverlayGl, DrawsWhatSoftDraws) {
    testing::OverlayScene gl(engine::render::gl::createGlBackend());
    testing::OverlayScene soft(engine::render::soft::createSoftBackend({1, 64, false}));
    auto content = [](const testing::OverlayScene& s) {
        OverlayContent c;
        c.images.push_back({s.source, {}, {30, 20, 8, 6}, {4, 34}, 4});
        c.text.push_back(layoutText({"gl 4.56 ms", "hud"}, {6, 4}, 1));
        return c;
    };
    const engine::render::Readback a = gl.render(content(gl)), b = soft.render(content(soft));
    const OverlayContent c = content(soft);
    const PixelRect box = c.text[0].box, inset = c.images[0].target();
    int overOneCode = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            for (int ch = 0; ch < 4; ++ch) {
                const float d = std::abs(a.at(x, y, ch) - b.at(x, y, ch));
                if (!box.contains(x, y) || inset.contains(x, y)) {
                    ASSERT_EQ(d, 0.0f) << x << "," << y << " channel " << ch;
                }
                overOneCode += d > 1.5f / 255.0f;
            }
    EXPECT_EQ(overOneCode, 0);
}

}  // namespace
}  // namespace hud
