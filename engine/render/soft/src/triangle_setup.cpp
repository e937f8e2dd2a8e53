#include "triangle_setup.hpp"

#include <algorithm>
#include <cmath>

namespace engine::render::soft {
namespace {

// Guard band: vertices stay within +-2^20 pixels, so 24.8 fixed-point coordinates fit
// in 29 bits and edge-function products in 58 bits of an int64.
constexpr double kGuardBandPixels = double(1 << 20);

// A clip plane as dot(plane, position) >= 0.
using ClipPlane = glm::vec4;

struct Polygon {
    std::array<ClipVertex, 12> vertices;
    int count = 0;
};

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, float t) {
    ClipVertex r;
    r.position = a.position + (b.position - a.position) * t;
    for (int i = 0; i < kAttributeCount; ++i) r.attributes[i] = a.attributes[i] + (b.attributes[i] - a.attributes[i]) * t;
    return r;
}

// Sutherland-Hodgman against one plane, in homogeneous clip space where attributes are
// still linear.
Polygon clip(const Polygon& in, const ClipPlane& plane) {
    Polygon out;
    for (int i = 0; i < in.count; ++i) {
        const ClipVertex& cur = in.vertices[i];
        const ClipVertex& next = in.vertices[(i + 1) % in.count];
        const float dc = glm::dot(plane, cur.position);
        const float dn = glm::dot(plane, next.position);
        if (dc >= 0.0f) out.vertices[out.count++] = cur;
        if ((dc >= 0.0f) != (dn >= 0.0f)) out.vertices[out.count++] = lerp(cur, next, dc / (dc - dn));
    }
    return out;
}

struct ScreenVertex {
    std::int64_t x, y;  // 24.8 fixed point, y down
    double z, inverseW;
    std::array<double, kAttributeCount> attributeOverW;
};

// Plane through the three values, anchored at vertex 0 so evaluation subtracts small numbers.
Plane makePlane(const ScreenVertex* v, const double* f, double inverseDenominator) {
    const double x1 = double(v[1].x - v[0].x) / kSubpixelScale, y1 = double(v[1].y - v[0].y) / kSubpixelScale;
    const double x2 = double(v[2].x - v[0].x) / kSubpixelScale, y2 = double(v[2].y - v[0].y) / kSubpixelScale;
    const double f1 = f[1] - f[0], f2 = f[2] - f[0];
    const double dx = (f1 * y2 - f2 * y1) * inverseDenominator;
    const double dy = (f2 * x1 - f1 * x2) * inverseDenominator;
    return {static_cast<float>(f[0]), static_cast<float>(dx), static_cast<float>(dy)};
}

void emit(const ScreenVertex* sv, const Viewport& vp, const RasterState& raster, std::uint32_t drawIndex,
          std::vector<SetupTriangle>& out, SetupCounters& counters) {
    ScreenVertex v[3] = {sv[0], sv[1], sv[2]};
    std::int64_t area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
    if (area == 0) {
        ++counters.dropped;
        return;
    }
    // y points down on screen, so a triangle counter-clockwise as displayed (GL's front
    // face by default) has a negative area here.
    const bool counterClockwise = area < 0;
    const bool frontFacing = (raster.frontFace == Winding::CounterClockwise) == counterClockwise;
    if ((raster.cull == CullMode::Back && !frontFacing) || (raster.cull == CullMode::Front && frontFacing)) {
        ++counters.dropped;
        return;
    }
    if (area < 0) {
        std::swap(v[1], v[2]);
        area = -area;
    }

    SetupTriangle t;
    t.drawIndex = drawIndex;
    t.frontFacing = frontFacing;
    const std::int64_t minXf = std::min({v[0].x, v[1].x, v[2].x}), maxXf = std::max({v[0].x, v[1].x, v[2].x});
    const std::int64_t minYf = std::min({v[0].y, v[1].y, v[2].y}), maxYf = std::max({v[0].y, v[1].y, v[2].y});
    // Conservative pixel box: every pixel any sample of which might be covered.
    t.minX = std::max<std::int64_t>(vp.scissor.x, minXf >> kSubpixelBits);
    t.minY = std::max<std::int64_t>(vp.scissor.y, minYf >> kSubpixelBits);
    t.maxX = std::min<std::int64_t>(vp.scissor.x + vp.scissor.width - 1, maxXf >> kSubpixelBits);
    t.maxY = std::min<std::int64_t>(vp.scissor.y + vp.scissor.height - 1, maxYf >> kSubpixelBits);
    if (t.minX > t.maxX || t.minY > t.maxY) {
        ++counters.dropped;
        return;
    }

    for (int i = 0; i < 3; ++i) {
        const ScreenVertex& p = v[i];
        const ScreenVertex& q = v[(i + 1) % 3];
        const std::int64_t dx = q.x - p.x, dy = q.y - p.y;
        t.a[i] = -dy;
        t.b[i] = dx;
        t.c[i] = dy * p.x - dx * p.y;
        // Top-left rule (y down, clockwise as stored): a top edge runs right, a left edge
        // runs up. Other edges exclude samples exactly on them.
        const bool topLeft = (dy == 0 && dx > 0) || dy < 0;
        if (!topLeft) t.c[i] -= 1;
    }

    const double originX = double(v[0].x) / kSubpixelScale, originY = double(v[0].y) / kSubpixelScale;
    t.originX = static_cast<float>(originX);
    t.originY = static_cast<float>(originY);
    const double inverseDenominator = double(kSubpixelScale) * kSubpixelScale / double(area);
    const double z[3] = {v[0].z, v[1].z, v[2].z};
    const double iw[3] = {v[0].inverseW, v[1].inverseW, v[2].inverseW};
    t.depth = makePlane(v, z, inverseDenominator);
    t.inverseW = makePlane(v, iw, inverseDenominator);
    for (int k = 0; k < kAttributeCount; ++k) {
        const double f[3] = {v[0].attributeOverW[k], v[1].attributeOverW[k], v[2].attributeOverW[k]};
        t.attributeOverW[k] = makePlane(v, f, inverseDenominator);
    }
    out.push_back(t);
}

bool finite(const ClipVertex& v) {
    return std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z) &&
           std::isfinite(v.position.w);
}

}  // namespace

void setupTriangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, const Viewport& vp,
                   const RasterState& raster, std::uint32_t drawIndex, std::vector<SetupTriangle>& out,
                   SetupCounters& counters) {
    if (!finite(v0) || !finite(v1) || !finite(v2)) {
        ++counters.dropped;
        return;
    }
    // Guard band in NDC: |x_ndc| <= gx keeps |x_pixels| <= 2^20 for this viewport.
    const float gx = static_cast<float>(kGuardBandPixels / vp.width - 1.0);
    const float gy = static_cast<float>(kGuardBandPixels / vp.height - 1.0);
    const ClipPlane planes[] = {
        {0.0f, 0.0f, 1.0f, 0.0f},   // z >= 0 (depth 0: the far plane under reverse-Z)
        {0.0f, 0.0f, -1.0f, 1.0f},  // z <= w
        {0.0f, 0.0f, 0.0f, 1.0f},   // w >= 0 (with the two above, only w = 0 edge cases)
        {-1.0f, 0.0f, 0.0f, gx}, {1.0f, 0.0f, 0.0f, gx}, {0.0f, -1.0f, 0.0f, gy}, {0.0f, 1.0f, 0.0f, gy},
    };

    Polygon poly;
    poly.vertices[0] = v0;
    poly.vertices[1] = v1;
    poly.vertices[2] = v2;
    poly.count = 3;
    for (const ClipPlane& plane : planes) {
        const float d0 = glm::dot(plane, poly.vertices[0].position), d1 = glm::dot(plane, poly.vertices[1].position),
                    d2 = glm::dot(plane, poly.vertices[2].position);
        if (poly.count == 3 && d0 >= 0.0f && d1 >= 0.0f && d2 >= 0.0f) continue;  // trivially inside
        poly = clip(poly, plane);
        if (poly.count < 3) {
            ++counters.dropped;
            return;
        }
    }

    std::array<ScreenVertex, 12> screen;
    for (int i = 0; i < poly.count; ++i) {
        const ClipVertex& c = poly.vertices[i];
        if (!(c.position.w > 0.0f)) {  // on the w = 0 plane exactly: nothing visible
            ++counters.dropped;
            return;
        }
        const double inverseW = 1.0 / double(c.position.w);
        const double x = (double(c.position.x) * inverseW * 0.5 + 0.5) * vp.width;
        const double y = (0.5 - double(c.position.y) * inverseW * 0.5) * vp.height;  // NDC +y is the top row
        ScreenVertex& s = screen[i];
        s.x = std::llround(x * kSubpixelScale);
        s.y = std::llround(y * kSubpixelScale);
        s.z = std::clamp(double(c.position.z) * inverseW, 0.0, 1.0);
        s.inverseW = inverseW;
        for (int k = 0; k < kAttributeCount; ++k) s.attributeOverW[k] = double(c.attributes[k]) * inverseW;
    }
    for (int i = 1; i + 1 < poly.count; ++i) {
        const ScreenVertex fan[3] = {screen[0], screen[i], screen[i + 1]};
        emit(fan, vp, raster, drawIndex, out, counters);
    }
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
