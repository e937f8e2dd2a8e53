// SPDX-License-Identifier: MIT
// racer --compare on the soft backend (compare_frame_check.hpp), its layout and crop choice
// (compare_layout.hpp) and its flag (racer_options.hpp).
#include <gtest/gtest.h>

#include "compare_frame_check.hpp"
#include "compare_layout.hpp"
#include "engine/core/usage_error.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "racer_options.hpp"

namespace racer {
namespace {

TEST(CompareFrame, HalvesAreEachTechniquesOwnFrameBitForBit) {
    auto soft = engine::render::soft::createSoftBackend({2, 64, false});
    testing::expectHalvesAreEachTechniquesOwnFrame(*soft);
}

bool overlaps(const hud::PixelRect& a, const hud::PixelRect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}
bool within(const hud::PixelRect& r, int w, int h) {
    return r.x >= 0 && r.y >= 0 && r.x + r.width <= w && r.y + r.height <= h;
}

TEST(CompareLayout, LabelsAndInsetsSitInTheirHalvesInsideTheFrame) {
    for (auto [w, h] : {std::pair{1280, 720}, std::pair{640, 360}, std::pair{320, 180}}) {
        const CompareLayout l = compareLayout(w, h, "ssam", "alpha-test");
        EXPECT_EQ(l.split, w / 2);
        EXPECT_LE(l.leftLabel.box.x + l.leftLabel.box.width, l.split);
        EXPECT_GE(l.rightLabel.box.x, l.split);
        EXPECT_LE(l.leftInset.x + l.leftInset.width + l.border, l.split);
        EXPECT_GE(l.rightInset.x - l.border, l.split);
        EXPECT_EQ(l.leftInset.width, kInsetZoom * l.crop.x);
        EXPECT_EQ(l.rightInset.height, kInsetZoom * l.crop.y);
        const hud::PixelRect crop{l.searchArea.x, l.searchArea.y, l.crop.x, l.crop.y};
        for (const hud::PixelRect& r : compareMarks(l, crop)) EXPECT_TRUE(within(r, w, h)) << w << "x" << h;
        // The crop is searched clear of the labels and insets (with their frames).
        const std::vector<hud::PixelRect> marks = compareMarks(l, crop);
        for (std::size_t i = 0; i < 4; ++i) EXPECT_FALSE(overlaps(l.searchArea, marks[i])) << w << "x" << h << " " << i;
        EXPECT_GE(l.searchArea.height, l.crop.y);
    }
}

TEST(CompareLayout, TheCropIsWhereTheFramesDifferMost) {
    const int w = 64, h = 40;
    std::vector<float> d(std::size_t(w * h), 0.01f);
    for (int y = 20; y < 26; ++y)
        for (int x = 41; x < 47; ++x) d[std::size_t(y * w + x)] = 1.0f;  // the foliage edge
    const hud::PixelRect crop = mostDifferentCrop(d, w, h, {6, 6}, {0, 0, w, h});
    EXPECT_EQ(crop, (hud::PixelRect{41, 20, 6, 6}));
    // Kept inside the search area, even when the difference is elsewhere.
    const hud::PixelRect kept = mostDifferentCrop(d, w, h, {6, 6}, {0, 0, 30, 40});
    EXPECT_LE(kept.x + kept.width, 30);
    // Equal sums: the first, top-most then left-most.
    EXPECT_EQ(mostDifferentCrop(std::vector<float>(std::size_t(w * h), 0.0f), w, h, {4, 4}, {3, 5, 20, 20}),
              (hud::PixelRect{3, 5, 4, 4}));
    // An area smaller than the crop: its corner.
    EXPECT_EQ(mostDifferentCrop(d, w, h, {10, 10}, {2, 2, 5, 5}), (hud::PixelRect{2, 2, 10, 10}));
}

TEST(CompareFlag, TwoKnownTechniquesOrAUsageError) {
    const ComparedPair p = parseCompare("ssam,alpha-test");
    EXPECT_EQ(p.left, transparency::TechniqueKind::Ssam);
    EXPECT_EQ(p.right, transparency::TechniqueKind::AlphaTest);
    EXPECT_EQ(parseCompare("wboit,wboit").left, transparency::TechniqueKind::Wboit);
    for (const char* bad : {"", "ssam", "ssam,", ",ssam", "ssam,alpha-test,a2c", "ssam,sorting-hat", "SSAM,alpha-test",
                            "ssam alpha-test"})
        EXPECT_THROW(parseCompare(bad), engine::UsageError) << bad;
}

}  // namespace
}  // namespace racer
