// SPDX-License-Identifier: MIT
#pragma once
// racer's HUD over the racing frame (frame_renderer.hpp setHud): the frame with the HUD
// differs from the frame without it inside the HUD's box and equals it, bit for bit,
// everywhere else -- on whichever backend renders both.
#include <gtest/gtest.h>

#include "hud_text.hpp"
#include "racing_frame.hpp"

namespace racer::testing {

inline void expectHudOnlyInsideItsBox(engine::render::Backend& backend) {
    RacingFrame plain(backend), withHud(backend);
    HudFacts facts{"ssam", backend.name(), kWidth, kHeight, "previous frame", 12.5, {{"opaque", 3.25, false}}, ""};
    withHud.renderer.setHud(hudLines(facts));
    plain.run(0, 3);
    withHud.run(0, 3);
    const hud::PixelRect box = withHud.renderer.hudBox();
    EXPECT_FALSE(plain.renderer.hudShown());
    EXPECT_EQ(plain.renderer.hudBox(), hud::PixelRect{});
    ASSERT_GT(box.width, 0);
    ASSERT_GT(box.height, 0);
    const engine::render::Readback a = backend.readback(plain.renderer.color());
    const engine::render::Readback b = backend.readback(withHud.renderer.color());
    int outsideDiffers = 0, insideDiffers = 0, inside = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            bool same = true;
            for (int c = 0; c < 4; ++c) same = same && a.at(x, y, c) == b.at(x, y, c);
            if (box.contains(x, y)) {
                ++inside;
                insideDiffers += !same;
            } else {
                outsideDiffers += !same;
            }
        }
    EXPECT_EQ(outsideDiffers, 0) << "pixels outside the HUD box changed";
    // The box is translucent dark over a bright sky and scene: nearly all of it changes.
    EXPECT_GT(insideDiffers, inside * 9 / 10) << insideDiffers << " of " << inside;
}

}  // namespace racer::testing
