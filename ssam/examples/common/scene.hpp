// SPDX-License-Identifier: MIT
#pragma once
// The examples' scene, as data, so the test that checks their images (tests/capture/gl) computes
// the expected pixels from the same numbers. Orthographic front view: world x, y in [-1, 1] are
// the screen (y up), z in [0, 1] is depth (0 nearest), mapped to OpenGL's default clip space.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gl_example {

constexpr int kWidth = 512, kHeight = 512;
constexpr std::array<float, 3> kSky{0.55f, 0.70f, 0.90f};

struct Rect3 {
    float x0, y0, x1, y1;
    float zLeft, zRight;         // depth at x0 and at x1 (crossing cards lean in depth)
    std::array<float, 4> color;  // opaque: colour; foliage: tint rgb and alpha factor
};

constexpr Rect3 kGround{-1.0f, -1.0f, 1.0f, -0.3f, 0.9f, 0.9f, {0.35f, 0.28f, 0.18f, 1.0f}};
constexpr Rect3 kBox{0.35f, -0.6f, 0.85f, 0.2f, 0.5f, 0.5f, {0.60f, 0.25f, 0.20f, 1.0f}};
constexpr Rect3 kBoxTop{0.35f, 0.2f, 0.85f, 0.3f, 0.5f, 0.5f, {0.75f, 0.40f, 0.30f, 1.0f}};
// The host's transparent pass (--mist): pale mist over the whole frame, behind every card and in
// front of the ground and the sky, alpha-blended and depth-tested without depth writes. After SSAM
// it is cut where the colour pass wrote foliage depth; before SSAM (behind all foliage, it may go
// there) it is the exact answer the later pass approximates.
constexpr Rect3 kMist{-1.0f, -1.0f, 1.0f, 1.0f, 0.85f, 0.85f, {0.95f, 0.95f, 0.95f, 0.6f}};

// Foliage cards (leaf texture * tint, alpha * texture alpha). A and B cross in depth at x = -0.15
// (A nearer on the left); C is alone over the sky; D is behind the box.
constexpr Rect3 kCardA{-0.8f, -0.5f, 0.2f, 0.7f, 0.3f, 0.7f, {1.0f, 1.0f, 1.0f, 0.6f}};
constexpr Rect3 kCardB{-0.5f, -0.4f, 0.5f, 0.8f, 0.7f, 0.3f, {0.55f, 0.85f, 1.0f, 0.35f}};
constexpr Rect3 kCardC{0.3f, 0.4f, 0.9f, 0.9f, 0.4f, 0.4f, {1.0f, 0.9f, 0.5f, 0.35f}};
constexpr Rect3 kCardD{0.45f, -0.9f, 1.0f, -0.1f, 0.8f, 0.8f, {0.8f, 1.0f, 0.8f, 0.8f}};
constexpr std::array<Rect3, 4> kCards{kCardA, kCardB, kCardC, kCardD};

// Each card is a strip of kCardRows rows (two triangles each), texture v from 0 at its base (y0)
// to 1 at its top (y1), so that a vertex shader can bend it: the host-shader example's wind moves
// a vertex at height h = v by windOffset(amplitude, h) in x, a bend that grows with height as a
// stem's does. Between rows the rasteriser interpolates: the offset inside a row is linear.
constexpr int kCardRows = 8;
constexpr float kDefaultWind = 0.3f;  // the host-shader example's amplitude (world units at the top)
inline float windOffset(float amplitude, float h) { return amplitude * h * h; }
inline float bentOffset(float amplitude, float v) {
    const float row = std::clamp(v, 0.0f, 1.0f) * kCardRows;
    const int below = std::min(static_cast<int>(row), kCardRows - 1);
    const float t = row - static_cast<float>(below);
    const float h0 = static_cast<float>(below) / kCardRows, h1 = static_cast<float>(below + 1) / kCardRows;
    return windOffset(amplitude, h0) + (windOffset(amplitude, h1) - windOffset(amplitude, h0)) * t;
}

// A vertex of the host's quads: world position, then the texture coordinates.
struct Vertex {
    float x, y, z, u, v;
};

// A quad as `rows` rows of two triangles, v from 0 (y0) to 1 (y1); opaque quads use one row.
inline void appendStrip(std::vector<Vertex>& out, const Rect3& r, int rows) {
    for (int row = 0; row < rows; ++row) {
        const float v0 = static_cast<float>(row) / rows, v1 = static_cast<float>(row + 1) / rows;
        const float ya = r.y0 + (r.y1 - r.y0) * v0, yb = r.y0 + (r.y1 - r.y0) * v1;
        const Vertex a{r.x0, ya, r.zLeft, 0, v0}, b{r.x1, ya, r.zRight, 1, v0}, c{r.x1, yb, r.zRight, 1, v1},
            d{r.x0, yb, r.zLeft, 0, v1};
        out.insert(out.end(), {a, b, c, a, c, d});
    }
}

// The procedural leaf: a disc with a uniform core (r < 0.6), darkening towards the rim, alpha 1
// inside r < 0.75 falling linearly to 0 at r = 1 (the soft edge SSAM blends), thin darker veins.
constexpr int kLeafSize = 64;
inline std::array<std::uint8_t, 4> leafTexel(int x, int y) {
    const float u = (x + 0.5f) / kLeafSize, v = (y + 0.5f) / kLeafSize;
    const float du = (u - 0.5f) * 2.0f, dv = (v - 0.5f) * 2.0f;
    const float r = std::sqrt(du * du + dv * dv);
    float shade = r < 0.6f ? 1.0f : 1.0f - 0.6f * (r - 0.6f) / 0.4f;
    const bool vein = r >= 0.6f && (std::fabs(du) < 0.03f || std::fabs(std::fabs(du) - std::fabs(dv)) < 0.04f);
    if (vein) shade *= 0.75f;
    const float alpha = std::clamp(r < 0.75f ? 1.0f : 1.0f - (r - 0.75f) / 0.25f, 0.0f, 1.0f);
    auto code = [](float f) { return static_cast<std::uint8_t>(std::lround(std::clamp(f, 0.0f, 1.0f) * 255.0f)); };
    return {code(0.30f * shade), code(0.62f * shade), code(0.20f * shade), code(alpha)};
}

// The window pixel (column, row from the top) whose centre is nearest to world (x, y).
inline std::array<int, 2> pixelAt(float x, float y) {
    return {static_cast<int>((x * 0.5f + 0.5f) * kWidth), static_cast<int>((0.5f - y * 0.5f) * kHeight)};
}

}  // namespace gl_example
