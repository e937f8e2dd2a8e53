// SPDX-License-Identifier: MIT
#include "compare_layout.hpp"

#include <algorithm>
#include <cmath>

namespace racer {

namespace {

constexpr glm::vec4 kFrameColor{0.95f, 0.85f, 0.2f, 1.0f};  // inset frames and the crop's outline

// The four sides of `r` grown by `border` pixels, outside it.
std::vector<hud::PixelRect> outline(const hud::PixelRect& r, int border) {
    return {{r.x - border, r.y - border, r.width + 2 * border, border},
            {r.x - border, r.y + r.height, r.width + 2 * border, border},
            {r.x - border, r.y, border, r.height},
            {r.x + r.width, r.y, border, r.height}};
}

hud::PixelRect grown(const hud::PixelRect& r, int by) {
    return {r.x - by, r.y - by, r.width + 2 * by, r.height + 2 * by};
}

}  // namespace

CompareLayout compareLayout(int width, int height, const std::string& left, const std::string& right) {
    CompareLayout l;
    l.width = width;
    l.height = height;
    l.split = width / 2;
    l.scale = hud::textScaleFor(height);
    l.border = 2 * l.scale;
    const int margin = 4 * l.scale;
    // Labels at the top, against the split.
    l.leftLabel = hud::layoutText({left}, {0, margin}, l.scale);
    const int shift = l.split - margin - l.leftLabel.box.width;
    l.leftLabel = hud::layoutText({left}, {shift, margin}, l.scale);
    l.rightLabel = hud::layoutText({right}, {l.split + margin, margin}, l.scale);
    // Insets: a crop of 1/20 x 1/15 of the frame, zoomed 4x (a fifth of the width, 4/15 of
    // the height), in the bottom corners, clear of the car in the middle.
    l.crop = {std::max(1, width / 20), std::max(1, height / 15)};
    const int insetW = l.crop.x * kInsetZoom, insetH = l.crop.y * kInsetZoom;
    const int insetY = height - margin - l.border - insetH;
    l.leftInset = {margin + l.border, insetY, insetW, insetH};
    l.rightInset = {width - margin - l.border - insetW, insetY, insetW, insetH};
    const int top = l.leftLabel.box.y + l.leftLabel.box.height + margin + l.border;
    const int bottom = insetY - l.border - margin - l.border;
    l.searchArea = {l.border, top, width - 2 * l.border, std::max(0, bottom - top)};
    return l;
}

std::vector<float> frameDifference(const engine::render::Readback& a, const engine::render::Readback& b) {
    std::vector<float> d(std::size_t(a.width) * std::size_t(a.height), 0.0f);
    if (a.width != b.width || a.height != b.height) return d;
    const int channels = std::min({a.channels, b.channels, 3});
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            float sum = 0.0f;
            for (int c = 0; c < channels; ++c) sum += std::abs(a.at(x, y, c) - b.at(x, y, c));
            d[std::size_t(y) * std::size_t(a.width) + std::size_t(x)] = sum;
        }
    return d;
}

hud::PixelRect mostDifferentCrop(const std::vector<float>& difference, int width, int height, glm::ivec2 crop,
                                 const hud::PixelRect& area) {
    // The area clipped to the frame; a crop that does not fit sits at the area's corner.
    const int x0 = std::max(0, area.x), y0 = std::max(0, area.y);
    const int x1 = std::min(width, area.x + area.width), y1 = std::min(height, area.y + area.height);
    hud::PixelRect best{x0, y0, crop.x, crop.y};
    if (x1 - x0 < crop.x || y1 - y0 < crop.y) return best;
    // Summed-area table in double: exact enough for any frame size.
    const std::size_t stride = std::size_t(width) + 1;
    std::vector<double> sat(stride * (std::size_t(height) + 1), 0.0);
    for (int y = 0; y < height; ++y) {
        double row = 0.0;
        for (int x = 0; x < width; ++x) {
            row += difference[std::size_t(y) * std::size_t(width) + std::size_t(x)];
            sat[(std::size_t(y) + 1) * stride + std::size_t(x) + 1] =
                sat[std::size_t(y) * stride + std::size_t(x) + 1] + row;
        }
    }
    auto sum = [&](int x, int y) {
        const std::size_t a = std::size_t(y) * stride + std::size_t(x), b = a + std::size_t(crop.x);
        const std::size_t c = (std::size_t(y) + std::size_t(crop.y)) * stride + std::size_t(x),
                          d = c + std::size_t(crop.x);
        return sat[d] - sat[b] - sat[c] + sat[a];
    };
    double bestSum = -1.0;
    for (int y = y0; y + crop.y <= y1; ++y)
        for (int x = x0; x + crop.x <= x1; ++x)
            if (const double s = sum(x, y); s > bestSum) bestSum = s, best = {x, y, crop.x, crop.y};
    return best;
}

hud::OverlayContent compareOverlay(const CompareLayout& l, const hud::PixelRect& crop,
                                   engine::render::TextureHandle left, engine::render::TextureHandle right) {
    hud::OverlayContent c;
    c.images.push_back({right, {}, {l.split, 0, l.width - l.split, l.height}, {l.split, 0}, 1});
    for (const hud::PixelRect& inset : {l.leftInset, l.rightInset})
        for (const hud::PixelRect& side : outline(inset, l.border)) c.fills.push_back({side, kFrameColor});
    c.images.push_back({left, {}, crop, {l.leftInset.x, l.leftInset.y}, kInsetZoom});
    c.images.push_back({right, {}, crop, {l.rightInset.x, l.rightInset.y}, kInsetZoom});
    c.text = {l.leftLabel, l.rightLabel};
    // Fills draw over the images, so the outline shows on either half.
    for (const hud::PixelRect& side : outline(crop, std::max(1, l.scale))) c.fills.push_back({side, kFrameColor});
    return c;
}

std::vector<hud::PixelRect> compareMarks(const CompareLayout& l, const hud::PixelRect& crop) {
    return {l.leftLabel.box, l.rightLabel.box, grown(l.leftInset, l.border), grown(l.rightInset, l.border),
            grown(crop, std::max(1, l.scale))};
}

}  // namespace racer
