// SPDX-License-Identifier: MIT
#pragma once
// Where the side-by-side compare (racer --compare A,B) puts things, as pure functions of the
// frame size and the two images, so tests know which pixels are overlay: technique A on the
// left half, B on the right; each half labelled at the top next to the split; two insets at
// the bottom, next to the split, showing the same crop of A (left) and of B (right) zoomed 4x,
// framed; and the crop's outline in the frame. The crop is where A and B differ most.
#include <string>
#include <vector>

#include "engine/render/backend.hpp"
#include "hud/overlay.hpp"

namespace racer {

inline constexpr int kInsetZoom = 4;

struct CompareLayout {
    int width = 0, height = 0;
    int split = 0;  // the right half starts at this column
    int scale = 1;  // font and border pixels
    hud::TextPanel leftLabel, rightLabel;
    hud::PixelRect leftInset, rightInset;  // the zoomed crops (without their frames)
    int border = 2;                        // the insets' frames, each side
    glm::ivec2 crop{0};                    // the crop's size in frame pixels (insets are kInsetZoom times that)
    hud::PixelRect searchArea;             // where the crop may lie: below the labels, above the insets
};

CompareLayout compareLayout(int width, int height, const std::string& left, const std::string& right);

// Per pixel, the summed absolute difference of the RGB values of two frames of equal size.
std::vector<float> frameDifference(const engine::render::Readback& a, const engine::render::Readback& b);

// The crop of size `crop` inside `area` whose summed `difference` (width x height, row-major)
// is largest; the first (top-most, then left-most) of equal ones. Via a summed-area table:
// linear in the frame size.
hud::PixelRect mostDifferentCrop(const std::vector<float>& difference, int width, int height, glm::ivec2 crop,
                                 const hud::PixelRect& area);

// The overlay over the composed frame: B's right half, the insets from `left` and `right`
// (single-sampled colours of the frame's size) at `crop`, their frames, the crop's outline,
// the labels.
hud::OverlayContent compareOverlay(const CompareLayout& layout, const hud::PixelRect& crop,
                                   engine::render::TextureHandle left, engine::render::TextureHandle right);

// The rectangles of that overlay outside the plain halves (labels, insets with frames, the
// crop's outline): every pixel elsewhere is A's left of `split`, B's from it on.
std::vector<hud::PixelRect> compareMarks(const CompareLayout& layout, const hud::PixelRect& crop);

}  // namespace racer
