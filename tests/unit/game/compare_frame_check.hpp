// SPDX-License-Identifier: MIT
#pragma once
// racer --compare over the racing frame (frame_renderer.hpp setCompare): outside the
// overlay's labels, insets and crop outline, the left half is technique A's own frame and the
// right half B's, bit for bit, on whichever backend renders all three.
#include <gtest/gtest.h>

#include "racing_frame.hpp"

namespace racer::testing {

inline void expectHalvesAreEachTechniquesOwnFrame(engine::render::Backend& backend) {
    using transparency::TechniqueKind;
    RacingFrame compared(backend), left(backend), right(backend);
    compared.renderer.setCompare(TechniqueKind::AlphaTest);
    right.renderer.setTechnique(TechniqueKind::AlphaTest);
    ASSERT_EQ(compared.renderer.comparedTechnique(), TechniqueKind::AlphaTest);
    EXPECT_FALSE(left.renderer.comparedTechnique());
    compared.run(0, 3);
    left.run(0, 3);
    right.run(0, 3);
    const std::vector<hud::PixelRect> marks = compared.renderer.compareMarks();
    ASSERT_FALSE(marks.empty());
    const engine::render::Readback c = backend.readback(compared.renderer.color());
    const engine::render::Readback a = backend.readback(left.renderer.color());
    const engine::render::Readback b = backend.readback(right.renderer.color());
    auto same = [](const engine::render::Readback& p, const engine::render::Readback& q, int x, int y) {
        for (int ch = 0; ch < 4; ++ch)
            if (p.at(x, y, ch) != q.at(x, y, ch)) return false;
        return true;
    };
    const int split = kWidth / 2;
    int checked = 0, leftWrong = 0, rightWrong = 0, techniquesDiffer = 0, rightDiffers = 0, marked = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            techniquesDiffer += !same(a, b, x, y);
            bool overlay = false;
            for (const hud::PixelRect& r : marks) overlay = overlay || r.contains(x, y);
            if (overlay) {
                ++marked;
                continue;
            }
            ++checked;
            if (x < split) {
                leftWrong += !same(c, a, x, y);
            } else {
                rightWrong += !same(c, b, x, y);
                rightDiffers += !same(a, b, x, y);
            }
        }
    EXPECT_EQ(leftWrong, 0) << "left-half pixels that are not technique A's own";
    EXPECT_EQ(rightWrong, 0) << "right-half pixels that are not technique B's own";
    EXPECT_GT(checked, kWidth * kHeight / 2) << "the overlay covers most of the frame: the check says little";
    EXPECT_GT(marked, 0);
    EXPECT_GT(techniquesDiffer, 0) << "A and B draw the same frame: the check cannot tell the halves apart";
    EXPECT_GT(rightDiffers, 0) << "A and B agree on every checked right-half pixel: a missing copy would pass";
}

}  // namespace racer::testing
