// SPDX-License-Identifier: MIT
// The size racer's window renders its framebuffer at (game/src/render_size.hpp
// renderSizeFor): the framebuffer's own, or scaled down as a whole when a side exceeds the
// largest render target, so the camera's aspect still matches the window's.
#include <algorithm>

#include <gtest/gtest.h>

#include "engine/render/texture.hpp"
#include "render_size.hpp"

namespace racer {
namespace {

using engine::render::kMaxTextureDimension;

TEST(RenderSize, FollowsTheFramebufferUpToTheLargestTarget) {
    EXPECT_EQ(renderSizeFor(1280, 720), (FrameSize{1280, 720}));
    EXPECT_EQ(renderSizeFor(1, 1), (FrameSize{1, 1}));
    EXPECT_EQ(renderSizeFor(kMaxTextureDimension, kMaxTextureDimension),
              (FrameSize{kMaxTextureDimension, kMaxTextureDimension}));
    EXPECT_EQ(renderSizeFor(kMaxTextureDimension, 3), (FrameSize{kMaxTextureDimension, 3}));
}

TEST(RenderSize, ScalesLargerFramebuffersDownKeepingTheAspect) {
    EXPECT_EQ(renderSizeFor(20000, 40), (FrameSize{kMaxTextureDimension, 33}));  // 40 * 16384 / 20000 = 32.8
    EXPECT_EQ(renderSizeFor(32768, 16384), (FrameSize{kMaxTextureDimension, 8192}));
    EXPECT_EQ(renderSizeFor(100, 30000), (FrameSize{55, kMaxTextureDimension}));  // 54.6
    EXPECT_EQ(renderSizeFor(32767, 1), (FrameSize{kMaxTextureDimension, 1}));     // never 0
    for (const FrameSize fb : {FrameSize{16385, 9000}, FrameSize{30000, 30000}, FrameSize{17000, 2}}) {
        const FrameSize r = renderSizeFor(fb.width, fb.height);
        EXPECT_LE(std::max(r.width, r.height), kMaxTextureDimension);
        EXPECT_GE(std::min(r.width, r.height), 1);
        // The aspect stays within the rounding of the shorter side (half a pixel).
        EXPECT_NEAR(double(r.width) / r.height, double(fb.width) / fb.height,
                    double(fb.width) / fb.height * 0.5 / std::min(r.width, r.height) + 1e-9);
    }
}

}  // namespace
}  // namespace racer
