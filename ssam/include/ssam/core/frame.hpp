// SPDX-License-Identifier: MIT
#pragma once
// The plain data of a frame that every SSAM shares: world boxes around the foliage, the built-in
// colour program's light, the two foliage passes and what a frame reports. Host-neutral core:
// standard C++17 only.

namespace ssam {

// Pixels. ssam::gl: GL window coordinates (rows from the bottom unless GL_UPPER_LEFT); ssam::vk and
// the engine: rows from the top.
struct Rect {
    int x = 0, y = 0, width = 0, height = 0;
};

// An axis-aligned world-space box.
struct Box {
    float min[3] = {0.0f, 0.0f, 0.0f};
    float max[3] = {0.0f, 0.0f, 0.0f};
};

// The directional light of SSAM's built-in colour program (a host's own shaders light as they
// like). The default is unlit: colour = base colour.
struct Light {
    float towardLight[3] = {0.0f, 0.0f, 1.0f};  // world space, need not be normalised
    float color[3] = {0.0f, 0.0f, 0.0f};        // scales max(dot(n, towardLight), 0), double-sided
    float ambient[3] = {1.0f, 1.0f, 1.0f};
};

// The two passes that draw the host's foliage (§3.5.2, §3.5.3).
enum class FoliagePass : int { Mask, Color };
const char* foliagePassName(FoliagePass pass) noexcept;  // "mask", "colour"

struct FrameReport {
    bool foliageInView = false;  // false: nothing ran (a host drawing pass by pass calls nothing more)
    int batchesVisible = 0;      // the engine-hosted SSAM: batches in view (the host APIs: 0, they draw)
    int passesRun = 0;           // 0 when no foliage is in view, else 3 (mask, colour, composite)
    Rect compositeRegion;        // where the composite ran (see Rect for each host's rows)
};

}  // namespace ssam
