// SPDX-License-Identifier: MIT
#pragma once
// Text as pixel rectangles: stb_easy_font (Sean Barrett, public domain; Debian's libstb-dev)
// builds every glyph of its small bitmap font out of axis-aligned quads on an integer grid,
// so a line of text is a list of rectangles, scaled here by a whole number of pixels. They
// land on pixel edges, where every backend's rasterizer covers exactly the same pixels.
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace hud {

// x/y from the target's top-left corner, y down (engine::render::Rect's convention).
struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0;
    bool contains(int px, int py) const { return px >= x && py >= y && px < x + width && py < y + height; }
    bool operator==(const PixelRect&) const = default;
};

// A panel of text: the box behind it and the rectangles of its glyphs, all inside the box.
struct TextPanel {
    PixelRect box;
    std::vector<PixelRect> glyphs;
    int scale = 1;  // screen pixels per font pixel
};

inline constexpr int kTextPadding = 3;  // font pixels between the box's edge and the text

// `lines` top to bottom (printable ASCII; anything else is drawn as '?'), the box's top-left
// corner at `origin`, each font pixel `scale` x `scale` screen pixels (scale >= 1).
TextPanel layoutText(const std::vector<std::string>& lines, glm::ivec2 origin, int scale);

// The font scale that keeps text readable at a frame height: 1 below 600 px, 2 up to 1400, then 3.
int textScaleFor(int frameHeight);

}  // namespace hud
