// SPDX-License-Identifier: MIT
// modules/hud: text laid out as stb_easy_font's quads, scaled to whole pixels; overlays that
// change the pixels of their panels and nothing else; image panels that copy and zoom exactly.
#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "hud/text_layout.hpp"
#include "hud_scene.hpp"

namespace hud {
namespace {

using testing::kH;
using testing::kW;

bool inside(const PixelRect& outer, const PixelRect& inner) {
    return inner.x >= outer.x && inner.y >= outer.y && inner.x + inner.width <= outer.x + outer.width &&
           inner.y + inner.height <= outer.y + outer.height;
}

TEST(HudText, GlyphsLieInsideTheirBoxOnWholeScaledPixels) {
    for (int scale : {1, 2, 3}) {
        const TextPanel p = layoutText({"ssam | soft | 1280x720", "  12.34  opaque", "gjpqy"}, {5, 7}, scale);
        EXPECT_EQ(p.box.x, 5);
        EXPECT_EQ(p.box.y, 7);
        EXPECT_EQ(p.scale, scale);
        ASSERT_GT(p.glyphs.size(), 40u);
        for (const PixelRect& g : p.glyphs) {
            EXPECT_TRUE(inside(p.box, g)) << g.x << "," << g.y << " " << g.width << "x" << g.height;
            EXPECT_EQ((g.x - 5) % scale, 0);
            EXPECT_EQ(g.width % scale, 0);
            EXPECT_EQ(g.height % scale, 0);
        }
    }
}

TEST(HudText, BoxGrowsWithTheTextAndTheScale) {
    const TextPanel one = layoutText({"frame"}, {0, 0}, 1);
    const TextPanel longer = layoutText({"frame time"}, {0, 0}, 1);
    const TextPanel two = layoutText({"frame", "pass"}, {0, 0}, 1);
    const TextPanel twice = layoutText({"frame"}, {0, 0}, 2);
    EXPECT_GT(longer.box.width, one.box.width);
    EXPECT_EQ(longer.box.height, one.box.height);
    EXPECT_EQ(two.box.width, one.box.width);
    EXPECT_EQ(two.box.height, one.box.height + 12);  // stb_easy_font's line advance
    EXPECT_EQ(twice.box.width, 2 * one.box.width);
    EXPECT_EQ(twice.box.height, 2 * one.box.height);
    ASSERT_EQ(twice.glyphs.size(), one.glyphs.size());
    for (std::size_t i = 0; i < one.glyphs.size(); ++i) {
        EXPECT_EQ(twice.glyphs[i].x, 2 * one.glyphs[i].x);
        EXPECT_EQ(twice.glyphs[i].width, 2 * one.glyphs[i].width);
    }
    EXPECT_TRUE(layoutText({}, {0, 0}, 1).glyphs.empty());
    EXPECT_TRUE(layoutText({" "}, {0, 0}, 1).glyphs.empty());
}

TEST(HudText, UnprintableCharactersShowAsQuestionMarksAndBadScalesAreRefused) {
    EXPECT_EQ(layoutText({"a\tb\x01"}, {0, 0}, 1).glyphs, layoutText({"a?b?"}, {0, 0}, 1).glyphs);
    EXPECT_THROW(layoutText({"x"}, {0, 0}, 0), engine::Error);
    EXPECT_EQ(textScaleFor(90), 1);
    EXPECT_EQ(textScaleFor(720), 2);
    EXPECT_EQ(textScaleFor(2160), 3);
}

std::unique_ptr<engine::render::Backend> soft() { return engine::render::soft::createSoftBackend({2, 64, false}); }

bool samePixel(const engine::render::Readback& a, const engine::render::Readback& b, int x, int y) {
    for (int c = 0; c < 4; ++c)
        if (a.at(x, y, c) != b.at(x, y, c)) return false;
    return true;
}

TEST(HudOverlay, TextChangesItsBoxAndNothingElse) {
    testing::OverlayScene scene(soft());
    const engine::render::Readback plain = scene.render({});
    OverlayContent content;
    content.text.push_back(layoutText({"ssam 12.3 ms", "opaque 4.5"}, {10, 6}, 1));
    const PixelRect box = content.text[0].box;
    ASSERT_LT(box.x + box.width, kW);
    ASSERT_LT(box.y + box.height, kH);
    const engine::render::Readback with = scene.render(content);
    int changed = 0, bright = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            if (!box.contains(x, y)) {
                ASSERT_TRUE(samePixel(with, plain, x, y)) << "outside the box at " << x << "," << y;
                continue;
            }
            changed += !samePixel(with, plain, x, y);
            bright += with.at(x, y, 0) > 0.9f && with.at(x, y, 1) > 0.9f;
        }
    // The translucent box darkens the gradient under it (all but its darkest pixels); glyphs are light.
    EXPECT_GT(changed, box.width * box.height * 9 / 10);
    int glyphPixels = 0;
    for (const PixelRect& g : content.text[0].glyphs) glyphPixels += g.width * g.height;
    EXPECT_GT(bright, glyphPixels / 2);
}

TEST(HudOverlay, PanelsCopyAndZoomTexelForTexel) {
    testing::OverlayScene scene(soft());
    const engine::render::Readback plain = scene.render({});
    OverlayContent content;
    const PixelRect region{30, 20, 8, 6};
    content.images.push_back({scene.source, {}, region, {4, 30}, 4});           // 32x24 inset
    content.images.push_back({scene.source, {}, {50, 0, 40, 64}, {50, 0}, 1});  // a copied strip
    const engine::render::Readback with = scene.render(content);
    const engine::render::Readback source = scene.backend->readback(scene.source);
    const PixelRect inset = content.images[0].target(), strip{50, 0, 40, 64};
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            if (inset.contains(x, y)) {
                const int sx = region.x + (x - inset.x) / 4, sy = region.y + (y - inset.y) / 4;
                for (int c = 0; c < 4; ++c) ASSERT_EQ(with.at(x, y, c), source.at(sx, sy, c)) << x << "," << y;
            } else if (strip.contains(x, y)) {
                ASSERT_TRUE(samePixel(with, source, x, y)) << x << "," << y;  // sRGB codes survive the copy
            } else {
                ASSERT_TRUE(samePixel(with, plain, x, y)) << x << "," << y;
            }
        }
}

TEST(HudOverlay, PanelsBeyondTheTargetAreClippedAndBadZoomIsRefused) {
    testing::OverlayScene scene(soft());
    const engine::render::Readback plain = scene.render({});
    OverlayContent content;
    content.images.push_back({scene.source, {}, {0, 0, 20, 20}, {kW - 8, kH - 8}, 2});  // mostly off the target
    const engine::render::Readback with = scene.render(content);
    EXPECT_TRUE(samePixel(with, plain, kW - 9, kH - 9));
    EXPECT_FALSE(samePixel(with, plain, kW - 1, kH - 1));
    OverlayContent bad;
    bad.images.push_back({scene.source, {}, {0, 0, 4, 4}, {0, 0}, 65});
    EXPECT_THROW(scene.render(bad), engine::Error);
}

}  // namespace
}  // namespace hud
