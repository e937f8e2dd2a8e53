// SPDX-License-Identifier: MIT
#include "hud/text_layout.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/error.hpp"

// stb_easy_font is a single header of static functions; racer uses print, width and height.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb/stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace hud {

namespace {

// stb_easy_font's vertex: position and an RGBA8 colour (unused: the panel colours its text).
struct EasyFontVertex {
    float x, y, z;
    unsigned char color[4];
};
static_assert(sizeof(EasyFontVertex) == 16);

std::string printable(const std::string& line) {
    std::string s = line;
    for (char& c : s)
        if (c < 32 || c > 126) c = '?';
    return s;
}

}  // namespace

TextPanel layoutText(const std::vector<std::string>& lines, glm::ivec2 origin, int scale) {
    if (scale < 1) throw engine::Error("text scale " + std::to_string(scale) + " is not >= 1");
    TextPanel panel;
    panel.scale = scale;
    int width = 0, height = 0;
    int lineTop = 0;
    std::vector<EasyFontVertex> vertices;
    for (const std::string& raw : lines) {
        std::string line = printable(raw);
        // About 270 bytes a character (stb_easy_font.h): room for the worst case.
        vertices.resize(line.size() * 24 + 4);
        const int quads = stb_easy_font_print(0.0f, float(lineTop), line.data(), nullptr, vertices.data(),
                                              int(vertices.size() * sizeof(EasyFontVertex)));
        for (int q = 0; q < quads; ++q) {
            const EasyFontVertex* v = &vertices[std::size_t(q) * 4];
            float x0 = v[0].x, y0 = v[0].y, x1 = v[0].x, y1 = v[0].y;
            for (int k = 1; k < 4; ++k) {
                x0 = std::min(x0, v[k].x), y0 = std::min(y0, v[k].y);
                x1 = std::max(x1, v[k].x), y1 = std::max(y1, v[k].y);
            }
            const int left = int(std::lround(x0)), top = int(std::lround(y0));
            const int w = int(std::lround(x1)) - left, h = int(std::lround(y1)) - top;
            if (w <= 0 || h <= 0) continue;
            panel.glyphs.push_back({origin.x + (kTextPadding + left) * scale, origin.y + (kTextPadding + top) * scale,
                                    w * scale, h * scale});
        }
        width = std::max(width, stb_easy_font_width(line.data()));
        lineTop += stb_easy_font_height(const_cast<char*>("X"));
        height = lineTop;
    }
    panel.box = {origin.x, origin.y, (width + 2 * kTextPadding) * scale, (height + 2 * kTextPadding) * scale};
    return panel;
}

int textScaleFor(int frameHeight) { return frameHeight < 600 ? 1 : frameHeight <= 1400 ? 2 : 3; }

}  // namespace hud
