// SPDX-License-Identifier: MIT
#include "engine/render/kernel/detail/triangle_setup.hpp"

#include <algorithm>
#include <cmath>

#include "tile_rasterizer.hpp"

namespace engine::render::soft {
namespace {

// Guard band: vertices stay within +-2^20 pixels, so 24.8 fixed-point coordinates fit
// in 29 bits and edge-function products in 58 bits of an int64.
constexpr double kGuardBandPixels = double(1 << 20);

// A clip plane as dot(plane, position) >= 0.
using ClipPlane = glm::dvec4;

// Clipping runs in double: a vertex clipped out of an edge between coordinates of +-1e6
// NDC is interpolated at that magnitude, where float rounding (~0.06 NDC per coordinate)
// moves the visible edge by pixels.
struct ClipPoint {
    glm::dvec4 position;
    std::array<double, kAttributeCount> attributes;
};

struct Polygon {
    std::array<ClipPoint, 12> vertices;
    int count = 0;
};

ClipPoint toClipPoint(const ClipVertex& v) {
    ClipPoint p;
    p.position = glm::dvec4(v.position);
    for (int i = 0; i < kAttributeCount; ++i) p.attributes[i] = v.attributes[i];
    return p;
}

ClipPoint lerp(const ClipPoint& a, const ClipPoint& b, double t) {
    ClipPoint r;
    r.position = a.position + (b.position - a.position) * t;
    for (int i = 0; i < kAttributeCount; ++i)
        r.attributes[i] = a.attributes[i] + (b.attributes[i] - a.attributes[i]) * t;
    return r;
}

// Sutherland-Hodgman against one plane, in homogeneous clip space where attributes are
// still linear.
Polygon clip(const Polygon& in, const ClipPlane& plane) {
    Polygon out;
    for (int i = 0; i < in.count; ++i) {
        const ClipPoint& cur = in.vertices[i];
        const ClipPoint& next = in.vertices[(i + 1) % in.count];
        const double dc = glm::dot(plane, cur.position);
        const double dn = glm::dot(plane, next.position);
        if (dc >= 0.0) out.vertices[out.count++] = cur;
        if ((dc >= 0.0) != (dn >= 0.0)) out.vertices[out.count++] = lerp(cur, next, dc / (dc - dn));
    }
    return out;
}

// Vertex 1 and 2 relative to vertex 0 in pixels, shared by all of a triangle's planes.
struct PlaneBasis {
    double x1, y1, x2, y2, inverseDenominator;
    PlaneBasis(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, double inverseDenominator)
        : x1(double(v1.x - v0.x) / kSubpixelScale), y1(double(v1.y - v0.y) / kSubpixelScale),
          x2(double(v2.x - v0.x) / kSubpixelScale), y2(double(v2.y - v0.y) / kSubpixelScale),
          inverseDenominator(inverseDenominator) {}
};

// Plane through the three values, anchored at vertex 0 so evaluation subtracts small numbers.
Plane makePlane(const PlaneBasis& b, double f0, double fv1, double fv2) {
    const double f1 = fv1 - f0, f2 = fv2 - f0;
    const double dx = (f1 * b.y2 - f2 * b.y1) * b.inverseDenominator;
    const double dy = (f2 * b.x1 - f1 * b.x2) * b.inverseDenominator;
    return {static_cast<float>(f0), static_cast<float>(dx), static_cast<float>(dy)};
}

// std::llround without the libm call: round half away from zero. Exact for |v| < 2^52
// (the truncation and v - trunc(v) are then exact), std::llround beyond that.
inline std::int64_t roundHalfAway(double v) {
    if (!(std::fabs(v) < 4503599627370496.0)) return std::llround(v);
    const std::int64_t i = static_cast<std::int64_t>(v);  // truncates toward zero
    const double fraction = v - static_cast<double>(i);
    // Without branches: the fraction's sign is the position's, so which way a vertex rounds
    // is as unpredictable as where it lies, and two mispredicted branches per coordinate
    // were the leading cost of set-up at 160x90.
    return i + std::int64_t(fraction >= 0.5) - std::int64_t(fraction <= -0.5);
}

// The edge functions of a triangle stored clockwise as displayed (v[0], v[1], v[2]), with the
// top-left rule folded into c.
void setEdges(SetupTriangle& t, const ScreenVertex* const v[3]) {
    for (int i = 0; i < 3; ++i) {
        const ScreenVertex& p = *v[i];
        const ScreenVertex& q = *v[(i + 1) % 3];
        const std::int64_t dx = q.x - p.x, dy = q.y - p.y;
        t.a[i] = -dy;
        t.b[i] = dx;
        t.c[i] = dy * p.x - dx * p.y;
        // Top-left rule (y down, clockwise as stored): a top edge runs right, a left edge
        // runs up. Other edges exclude samples exactly on them.
        const bool topLeft = (dy == 0 && dx > 0) || dy < 0;
        if (!topLeft) t.c[i] -= 1;
    }
}

// Whether beginTriangle() would keep the triangle (the same area, culling, box and
// tiny-coverage tests), without appending it: for the fans of clipped polygons, whose
// attributes are needed only if one of their triangles is kept.
bool survivesEmit(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, const Viewport& vp,
                  const RasterState& raster) {
    const std::int64_t area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (area == 0) return false;
    const bool frontFacing = (raster.frontFace == Winding::CounterClockwise) == (area < 0);
    if ((raster.cull == CullMode::Back && !frontFacing) || (raster.cull == CullMode::Front && frontFacing))
        return false;
    SetupTriangle t;  // only the box and the edges, as emit() makes them
    t.minX = int(std::max<std::int64_t>(vp.scissor.x, std::min({a.x, b.x, c.x}) >> kSubpixelBits));
    t.minY = int(std::max<std::int64_t>(vp.scissor.y, std::min({a.y, b.y, c.y}) >> kSubpixelBits));
    t.maxX =
        int(std::min<std::int64_t>(vp.scissor.x + vp.scissor.width - 1, std::max({a.x, b.x, c.x}) >> kSubpixelBits));
    t.maxY =
        int(std::min<std::int64_t>(vp.scissor.y + vp.scissor.height - 1, std::max({a.y, b.y, c.y}) >> kSubpixelBits));
    if (t.minX > t.maxX || t.minY > t.maxY) return false;
    if (!vp.pattern || !isTinyTriangle(t)) return true;
    const ScreenVertex* v[3] = {&a, &b, &c};
    if (area < 0) std::swap(v[1], v[2]);
    setEdges(t, v);
    return coversAnySample(t, *vp.pattern);
}

// A triangle appended to `out` with its facing, box and edges (beginTriangle): its vertices
// in the stored (clockwise) order and twice its area in sub-pixel units, for its planes.
struct BegunTriangle {
    std::size_t index = 0;  // in `out`
    const ScreenVertex* v[3] = {};
    std::int64_t area = 0;
};

// The area, culling, box and tiny-coverage tests, from the snapped positions alone: a
// triangle that passes them is appended to `out` with its facing, box and edges (its
// vertices' depth and attributes are not read yet); one that fails is counted dropped.
bool beginTriangle(const ScreenVertex& s0, const ScreenVertex& s1, const ScreenVertex& s2, const Viewport& vp,
                   const RasterState& raster, std::uint32_t drawIndex, std::vector<SetupTriangle>& out,
                   SetupCounters& counters, BegunTriangle& begun) {
    const ScreenVertex* v[3] = {&s0, &s1, &s2};  // swapped as pointers, not copied
    std::int64_t area = (v[1]->x - v[0]->x) * (v[2]->y - v[0]->y) - (v[1]->y - v[0]->y) * (v[2]->x - v[0]->x);
    if (area == 0) {
        ++counters.dropped;
        return false;
    }
    // y points down on screen, so a triangle counter-clockwise as displayed (GL's front
    // face by default) has a negative area here.
    const bool counterClockwise = area < 0;
    const bool frontFacing = (raster.frontFace == Winding::CounterClockwise) == counterClockwise;
    if ((raster.cull == CullMode::Back && !frontFacing) || (raster.cull == CullMode::Front && frontFacing)) {
        ++counters.dropped;
        return false;
    }
    if (area < 0) {
        std::swap(v[1], v[2]);
        area = -area;
    }

    const std::int64_t minXf = std::min({v[0]->x, v[1]->x, v[2]->x}), maxXf = std::max({v[0]->x, v[1]->x, v[2]->x});
    const std::int64_t minYf = std::min({v[0]->y, v[1]->y, v[2]->y}), maxYf = std::max({v[0]->y, v[1]->y, v[2]->y});
    // Conservative pixel box: every pixel any sample of which might be covered.
    const int minX = int(std::max<std::int64_t>(vp.scissor.x, minXf >> kSubpixelBits));
    const int minY = int(std::max<std::int64_t>(vp.scissor.y, minYf >> kSubpixelBits));
    const int maxX = int(std::min<std::int64_t>(vp.scissor.x + vp.scissor.width - 1, maxXf >> kSubpixelBits));
    const int maxY = int(std::min<std::int64_t>(vp.scissor.y + vp.scissor.height - 1, maxYf >> kSubpixelBits));
    if (minX > maxX || minY > maxY) {
        ++counters.dropped;
        return false;
    }

    SetupTriangle& t = out.emplace_back();  // built in place
    t.drawIndex = drawIndex;
    t.frontFacing = frontFacing;
    t.minX = minX, t.minY = minY, t.maxX = maxX, t.maxY = maxY;
    setEdges(t, v);
    if (vp.pattern && isTinyTriangle(t) && !coversAnySample(t, *vp.pattern)) {
        out.pop_back();
        ++counters.dropped;
        return false;
    }
    begun = {out.size() - 1, {v[0], v[1], v[2]}, area};
    return true;
}

// The begun triangle's depth and attribute planes, from its vertices' z and attributes.
void finishTriangle(const BegunTriangle& begun, std::vector<SetupTriangle>& out) {
    SetupTriangle& t = out[begun.index];
    const ScreenVertex* const* v = begun.v;
    const double originX = double(v[0]->x) / kSubpixelScale, originY = double(v[0]->y) / kSubpixelScale;
    t.originX = static_cast<float>(originX);
    t.originY = static_cast<float>(originY);
    const PlaneBasis basis(*v[0], *v[1], *v[2], double(kSubpixelScale) * kSubpixelScale / double(begun.area));
    t.depth = makePlane(basis, v[0]->z, v[1]->z, v[2]->z);
    t.inverseW = makePlane(basis, v[0]->inverseW, v[1]->inverseW, v[2]->inverseW);
    for (int k = 0; k < kAttributeCount; ++k)
        t.attributeOverW[k] =
            makePlane(basis, v[0]->attributeOverW[k], v[1]->attributeOverW[k], v[2]->attributeOverW[k]);
}

void emit(const ScreenVertex& s0, const ScreenVertex& s1, const ScreenVertex& s2, const Viewport& vp,
          const RasterState& raster, std::uint32_t drawIndex, std::vector<SetupTriangle>& out,
          SetupCounters& counters) {
    BegunTriangle begun;
    if (beginTriangle(s0, s1, s2, vp, raster, drawIndex, out, counters, begun)) finishTriangle(begun, out);
}

// glm::dot(plane, p) >= 0 for each of setupClippedTriangle's planes, without the products
// with their zero components: for finite p those are +-0, which change neither the sum's value
// nor its sign test (x + +-0 is x, or +-0 where x is 0, and +-0 >= 0 holds), and -z + w is the
// same IEEE operation as w - z. Every test is made (& rather than &&): no branch per plane.
bool insideEveryPlane(const glm::dvec4& p, double gx, double gy) {
    return (p.z >= 0.0) & (p.w - p.z >= 0.0) & (p.w >= 0.0) & (gx * p.w - p.x >= 0.0) & (p.x + gx * p.w >= 0.0) &
           (gy * p.w - p.y >= 0.0) & (p.y + gy * p.w >= 0.0);
}

// Guard band in NDC: |x_ndc| <= gx keeps |x_pixels| <= 2^20 for this viewport.
double guardBandX(const Viewport& vp) { return kGuardBandPixels / vp.width - 1.0; }
double guardBandY(const Viewport& vp) { return kGuardBandPixels / vp.height - 1.0; }

bool finite(const ClipVertex& v) {
    return std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z) &&
           std::isfinite(v.position.w);
}

// A vertex (w > 0) to the sub-pixel grid, with its 1/w.
void project(const glm::dvec4& c, const Viewport& vp, ScreenVertex& s) {
    const double inverseW = 1.0 / c.w;
    const double x = (c.x * inverseW * 0.5 + 0.5) * vp.width;
    const double y = (0.5 - c.y * inverseW * 0.5) * vp.height;  // NDC +y is the top row
    s.x = roundHalfAway(x * kSubpixelScale);
    s.y = roundHalfAway(y * kSubpixelScale);
    s.inverseW = inverseW;
}

// A projected vertex's depth and attributes over w, for the planes of a kept triangle.
template <typename Attribute>
void finishProjection(const glm::dvec4& c, Attribute attribute, ScreenVertex& s) {
    s.z = std::clamp(c.z * s.inverseW, 0.0, 1.0);
    for (int k = 0; k < kAttributeCount; ++k) s.attributeOverW[k] = attribute(k) * s.inverseW;
}

// A clipped polygon (`count` vertices, attributes filled) to screen space, then its fan of
// triangles emitted: the triangles of a fan none of which survives make no depth or
// attribute planes.
void projectAndEmit(const Polygon& poly, const Viewport& vp, const RasterState& raster, std::uint32_t drawIndex,
                    std::vector<SetupTriangle>& out, SetupCounters& counters) {
    const int count = poly.count;
    std::array<ScreenVertex, 12> screen;
    for (int i = 0; i < count; ++i) {
        const glm::dvec4& c = poly.vertices[i].position;
        if (!(c.w > 0.0)) {  // on the w = 0 plane exactly: nothing visible
            ++counters.dropped;
            return;
        }
        project(c, vp, screen[i]);
    }
    bool anySurvives = false;
    for (int i = 1; i + 1 < count && !anySurvives; ++i)
        anySurvives = survivesEmit(screen[0], screen[i], screen[i + 1], vp, raster);
    if (!anySurvives) {
        counters.dropped += std::uint64_t(count - 2);
        return;
    }
    for (int i = 0; i < count; ++i)
        finishProjection(
            poly.vertices[i].position, [&](int k) { return poly.vertices[i].attributes[k]; }, screen[i]);
    for (int i = 1; i + 1 < count; ++i) emit(screen[0], screen[i], screen[i + 1], vp, raster, drawIndex, out, counters);
}

// A triangle that crosses a clip plane (not every vertex inside every plane): its attributes
// filled, clipped in homogeneous space into a polygon, and the polygon's fan set up.
void setupClippedTriangle(ClipVertex (&v)[3], const AttributeSource& attributes, const Viewport& vp,
                          const RasterState& raster, std::uint32_t drawIndex, std::vector<SetupTriangle>& out,
                          SetupCounters& counters) {
    const double gx = guardBandX(vp), gy = guardBandY(vp);
    const ClipPlane planes[] = {
        {0.0, 0.0, 1.0, 0.0},   // z >= 0 (depth 0: the far plane under reverse-Z)
        {0.0, 0.0, -1.0, 1.0},  // z <= w
        {0.0, 0.0, 0.0, 1.0},   // w >= 0 (with the two above, only w = 0 edge cases)
        {-1.0, 0.0, 0.0, gx},  {1.0, 0.0, 0.0, gx}, {0.0, -1.0, 0.0, gy}, {0.0, 1.0, 0.0, gy},
    };
    attributes.fill(v);
    Polygon poly;
    poly.vertices[0] = toClipPoint(v[0]);
    poly.vertices[1] = toClipPoint(v[1]);
    poly.vertices[2] = toClipPoint(v[2]);
    poly.count = 3;
    for (const ClipPlane& plane : planes) {
        const double d0 = glm::dot(plane, poly.vertices[0].position), d1 = glm::dot(plane, poly.vertices[1].position),
                     d2 = glm::dot(plane, poly.vertices[2].position);
        if (poly.count == 3 && d0 >= 0.0 && d1 >= 0.0 && d2 >= 0.0) continue;  // trivially inside
        poly = clip(poly, plane);
        if (poly.count < 3) {
            ++counters.dropped;
            return;
        }
    }
    projectAndEmit(poly, vp, raster, drawIndex, out, counters);
}

}  // namespace

bool rejectedBeforeSetup(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, const Viewport& vp) {
    return !finite(v0) || !finite(v1) || !finite(v2) || outsideOnePlane(v0, v1, v2, vp);
}

bool outsideOnePlane(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, const Viewport& vp) {
    const ClipVertex* v[3] = {&v0, &v1, &v2};
    double magnitude = 0.0;
    for (const ClipVertex* p : v)
        magnitude = std::max(magnitude, double(std::fabs(p->position.x)) + std::fabs(p->position.y) +
                                            std::fabs(p->position.z) + std::fabs(p->position.w));
    const double margin = kFrustumRejectMargin * magnitude;
    const double kx = 1.0 + 2.0 / vp.width, ky = 1.0 + 2.0 / vp.height;
    // Each test: the signed distance beyond one plane, for all three vertices.
    auto all = [&](auto beyond) { return beyond(v0.position) && beyond(v1.position) && beyond(v2.position); };
    return all([&](const glm::vec4& p) { return double(p.x) - kx * p.w > margin; }) ||
           all([&](const glm::vec4& p) { return -double(p.x) - kx * p.w > margin; }) ||
           all([&](const glm::vec4& p) { return double(p.y) - ky * p.w > margin; }) ||
           all([&](const glm::vec4& p) { return -double(p.y) - ky * p.w > margin; }) ||
           all([&](const glm::vec4& p) { return -double(p.z) > margin; }) ||
           all([&](const glm::vec4& p) { return double(p.z) - p.w > margin; }) ||
           all([&](const glm::vec4& p) { return -double(p.w) > margin; });
}

namespace {
// For setupTriangle's callers, whose vertices come with their attributes.
class GivenAttributes final : public AttributeSource {
public:
    void fillVertex(int, ClipVertex&) const override {}
};
}  // namespace

void setupTriangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, const Viewport& vp,
                   const RasterState& raster, std::uint32_t drawIndex, std::vector<SetupTriangle>& out,
                   SetupCounters& counters) {
    if (rejectedBeforeSetup(v0, v1, v2, vp)) {
        ++counters.dropped;
        return;
    }
    ClipVertex vertices[3] = {v0, v1, v2};
    setupUnrejectedTriangle(vertices, GivenAttributes{}, vp, raster, drawIndex, out, counters);
}

void prepareVertex(PreparedVertex& v, const Viewport& vp) {
    v.finite = finite(v.clip);
    v.finished = false;
    const glm::dvec4 c(v.clip.position);
    v.inside = v.finite && insideEveryPlane(c, guardBandX(vp), guardBandY(vp));
    v.projectable = v.inside && c.w > 0.0;
    if (v.projectable) project(c, vp, v.screen);
}

void setupPreparedTriangle(PreparedVertex* const (&v)[3], const AttributeSource& attributes, const Viewport& vp,
                           const RasterState& raster, std::uint32_t drawIndex, std::vector<SetupTriangle>& out,
                           SetupCounters& counters) {
    if (!(v[0]->inside && v[1]->inside && v[2]->inside)) {
        ClipVertex clip[3] = {v[0]->clip, v[1]->clip, v[2]->clip};
        setupClippedTriangle(clip, attributes, vp, raster, drawIndex, out, counters);
        return;
    }
    // Inside every plane (most triangles): no polygon to build. A vertex on the w = 0 plane
    // exactly makes nothing visible; most dropped triangles (culled, off-screen, degenerate,
    // covering no sample) are known from the snapped positions and never ask for attributes.
    if (!(v[0]->projectable && v[1]->projectable && v[2]->projectable)) {
        ++counters.dropped;
        return;
    }
    BegunTriangle begun;
    if (!beginTriangle(v[0]->screen, v[1]->screen, v[2]->screen, vp, raster, drawIndex, out, counters, begun)) return;
    for (int k = 0; k < 3; ++k) {
        PreparedVertex& p = *v[k];
        if (p.finished) continue;
        attributes.fillVertex(k, p.clip);
        finishProjection(
            glm::dvec4(p.clip.position), [&](int a) { return double(p.clip.attributes[a]); }, p.screen);
        p.finished = true;
    }
    finishTriangle(begun, out);
}

void setupUnrejectedTriangle(ClipVertex (&v)[3], const AttributeSource& attributes, const Viewport& vp,
                             const RasterState& raster, std::uint32_t drawIndex, std::vector<SetupTriangle>& out,
                             SetupCounters& counters) {
    PreparedVertex prepared[3];
    for (int k = 0; k < 3; ++k) {
        prepared[k].clip = v[k];
        prepareVertex(prepared[k], vp);
    }
    PreparedVertex* const p[3] = {&prepared[0], &prepared[1], &prepared[2]};
    setupPreparedTriangle(p, attributes, vp, raster, drawIndex, out, counters);
}

SetupTriangle fullscreenTriangle(const Viewport& vp, std::uint32_t drawIndex) {
    SetupTriangle t;
    t.drawIndex = drawIndex;
    t.minX = vp.scissor.x;
    t.minY = vp.scissor.y;
    t.maxX = vp.scissor.x + vp.scissor.width - 1;
    t.maxY = vp.scissor.y + vp.scissor.height - 1;
    // Edges a = b = 0, c = 1: every sample is inside.
    t.c = {1, 1, 1};
    t.inverseW = {1.0f, 0.0f, 0.0f};
    return t;
}

}  // namespace engine::render::soft
