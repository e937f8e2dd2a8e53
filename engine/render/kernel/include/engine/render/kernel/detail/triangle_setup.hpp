// SPDX-License-Identifier: MIT
#pragma once
// From clip-space vertices to rasterizable triangles: homogeneous clipping against the
// near/far planes and a guard band, perspective divide, snapping to 24.8 fixed point,
// edge functions with the top-left rule, and the planes that interpolate depth and the
// perspective-correct attributes.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "engine/render/raster_state.hpp"

namespace engine::render::soft {

inline constexpr int kSubpixelBits = 8;
inline constexpr int kSubpixelScale = 1 << kSubpixelBits;

// Attributes carried per vertex: uv (2), normal (3), colour (4).
inline constexpr int kAttributeCount = 9;
enum AttributeSlot { kAttrU = 0, kAttrV = 1, kAttrNormal = 2, kAttrColor = 5 };

struct ClipVertex {
    glm::vec4 position;  // clip space, depth in [0, w]
    std::array<float, kAttributeCount> attributes;
};

// f(x, y) = value + dx * (x - originX) + dy * (y - originY), in pixels.
struct Plane {
    float value = 0.0f, dx = 0.0f, dy = 0.0f;
};

struct SetupTriangle {
    std::uint32_t drawIndex = 0;
    bool frontFacing = true;
    // Pixel bounding box, inclusive, already clipped to the viewport and scissor.
    int minX = 0, minY = 0, maxX = -1, maxY = -1;
    // Edge i is E(x, y) = a*x + b*y + c in sub-pixel units; inside when E >= 0 (the
    // top-left rule is folded into c).
    std::array<std::int64_t, 3> a{}, b{}, c{};
    float originX = 0.0f, originY = 0.0f;
    Plane depth;                                        // z/w, linear in screen space
    Plane inverseW;                                     // 1/w
    std::array<Plane, kAttributeCount> attributeOverW;  // attribute/w
};

struct SamplePattern;

struct Viewport {
    int width = 0, height = 0;
    Rect scissor;  // already intersected with the target
    // Set: a triangle whose pixel box is at most 2x2 pixels and that covers no sample of
    // this pattern is dropped before its depth and attribute planes are set up.
    const SamplePattern* pattern = nullptr;
};

struct SetupCounters {
    std::uint64_t dropped = 0;  // degenerate, NaN, fully clipped or culled
};

// Relative margin of the frustum rejects below: far above the rounding of the double
// clipping and projection (~1e-15) and of a float vertex transform (~1e-6, for callers that
// bound transformed boxes), so a reject never disagrees with the exact pipeline.
inline constexpr double kFrustumRejectMargin = 1e-5;

// Whether all three (finite) vertices lie beyond one clip plane by the margin: beyond the
// far/near planes or w = 0, or more than a pixel outside the viewport's sides. Such a
// triangle is one setupTriangle would clip away or drop by its pixel box anyway (every
// point of its clipped polygon is a convex combination of its vertices, so it stays beyond
// the plane, and a point a pixel outside the viewport snaps outside it), so rejecting it
// first changes no pixel; it skips the double-precision clipping and projection.
bool outsideOnePlane(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, const Viewport& viewport);

// What setupTriangle drops before any other work, from the positions alone (attributes
// are not read): a non-finite position, or outsideOnePlane. Such a triangle counts one dropped.
bool rejectedBeforeSetup(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, const Viewport& viewport);

// Clips, culls and sets up one triangle, appending 0..7 triangles to `out`.
void setupTriangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, const Viewport& viewport,
                   const RasterState& raster, std::uint32_t drawIndex, std::vector<SetupTriangle>& out,
                   SetupCounters& counters);

// Where set-up finds the attributes of a triangle's vertices when it needs them: the vertex
// stage computes normals and colours only for the triangles set-up keeps or clips (most of
// those it drops, culled or covering no sample, never need them).
class AttributeSource {
public:
    // Writes the attributes of vertex k (0, 1, 2) of the triangle (its position is already there).
    virtual void fillVertex(int k, ClipVertex& vertex) const = 0;
    void fill(ClipVertex (&vertices)[3]) const {
        for (int k = 0; k < 3; ++k) fillVertex(k, vertices[k]);
    }

protected:
    ~AttributeSource() = default;
};

// A vertex snapped to the sub-pixel grid: 24.8 fixed point, y down, with its depth, 1/w and
// attributes over w in double for the planes.
struct ScreenVertex {
    std::int64_t x = 0, y = 0;
    double z = 0.0, inverseW = 0.0;
    std::array<double, kAttributeCount> attributeOverW{};
};

// A vertex of an indexed draw worked out once for every triangle of an instance that uses it
// (prepareVertex): the per-vertex half of setupTriangle, whose per-triangle half
// (setupPreparedTriangle) then reads it. Each value is the one setupTriangle computes for that
// vertex, so sharing it changes no bit.
struct PreparedVertex {
    ClipVertex clip;           // position; attributes once `finished`
    bool finite = false;       // every position component finite (rejectedBeforeSetup)
    bool inside = false;       // inside every clip plane: no clipping needed
    bool projectable = false;  // inside, with w > 0: `screen` holds x, y and 1/w
    bool finished = false;     // attributes filled, `screen` holds z and attributes over w
    ScreenVertex screen;
};

// Fills everything of `v` but its attributes from v.clip.position.
void prepareVertex(PreparedVertex& v, const Viewport& viewport);

// setupUnrejectedTriangle for three prepared vertices (finite, the triangle not beyond one
// clip plane): vertex k's attributes are filled from `attributes` (fillVertex(k, ...)) the
// first time a kept triangle needs them.
void setupPreparedTriangle(PreparedVertex* const (&vertices)[3], const AttributeSource& attributes,
                           const Viewport& viewport, const RasterState& raster, std::uint32_t drawIndex,
                           std::vector<SetupTriangle>& out, SetupCounters& counters);

// setupTriangle for a triangle rejectedBeforeSetup has already kept (the vertex stage tests
// positions before it computes attributes), its attributes filled from `attributes` when they
// are first needed, at most once.
void setupUnrejectedTriangle(ClipVertex (&vertices)[3], const AttributeSource& attributes, const Viewport& viewport,
                             const RasterState& raster, std::uint32_t drawIndex, std::vector<SetupTriangle>& out,
                             SetupCounters& counters);

// A triangle whose bounding box is the scissor and whose edges accept everything: for
// full-screen programs, which need no geometry.
SetupTriangle fullscreenTriangle(const Viewport& viewport, std::uint32_t drawIndex);

}  // namespace engine::render::soft
