// SPDX-License-Identifier: MIT
// Clipping: triangles crossing the near plane (vertices behind the eye, w < 0, or between
// the eye and the near plane, z < 0) and the far plane, checked pixel by pixel against a ray
// cast of the same triangle (coverage, perspective-correct colour, depth); triangles spanning
// +-1e6 in NDC against the half-plane they cover and the same triangle drawn small; and
// degenerate, non-finite and invisible triangles, which must be dropped without a trace.
#include <cmath>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "../backend_fixture.hpp"

namespace ssam::test {
namespace {

constexpr int kSize = 32;
constexpr double kNear = 1.0, kFar = 100.0;

glm::mat4 projection() { return glm::perspectiveRH_ZO(glm::radians(90.0f), 1.0f, float(kNear), float(kFar)); }

struct RayHit {
    bool hit = false;
    glm::dvec3 barycentric{0.0};
    double depth = 0.0;  // window depth z/w in [0,1]
};

// The triangle (view space, camera at the origin looking down -z, 90 degree square frustum)
// seen through the point (ndcX, ndcY): hit where the ray meets the triangle between the near
// and far planes.
RayHit castRay(const glm::dvec3 (&v)[3], double ndcX, double ndcY) {
    const glm::dvec3 dir(ndcX, ndcY, -1.0);  // tan(45 deg) = 1
    const glm::dvec3 e1 = v[1] - v[0], e2 = v[2] - v[0];
    const glm::dvec3 p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    RayHit r;
    if (std::fabs(det) < 1e-12) return r;
    const glm::dvec3 s = -v[0];
    const double b1 = glm::dot(s, p) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double b2 = glm::dot(dir, q) / det;
    const double t = glm::dot(e2, q) / det;  // view distance along -z: the point is t * dir
    if (b1 < 0 || b2 < 0 || b1 + b2 > 1 || t < kNear || t > kFar) return r;
    r.hit = true;
    r.barycentric = {1.0 - b1 - b2, b1, b2};
    // perspectiveRH_ZO: z_clip = far/(near-far) * z + far*near/(near-far), w = -z, z = -t.
    const double zClip = kFar / (kNear - kFar) * -t + kFar * kNear / (kNear - kFar);
    r.depth = zClip / t;
    return r;
}

class ClipRig {
public:
    explicit ClipRig(render::Backend& gfx) : gfx_(gfx) {}

    // Draws the triangle (view space) with vertex colours red, green, blue and compares with
    // the ray cast; pixels whose coverage changes within 1/32 pixel of the centre are skipped.
    void check(const glm::dvec3 (&v)[3], const std::string& what) {
        const render::TextureHandle color = target(Format::RGBA32F);
        const render::TextureHandle depth = target(Format::D32F);
        std::vector<render::Vertex> tri(3);
        const glm::vec4 colors[3] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
        for (int i = 0; i < 3; ++i) {
            tri[i].position = glm::vec3(v[i]);
            tri[i].color = colors[i];
        }
        const render::BufferHandle vb =
            gfx_.createBuffer({"tri", render::BufferKind::Vertex, 3 * sizeof(render::Vertex)}, bytesOf(tri));
        render::PipelineDesc desc;
        desc.name = "clip";
        desc.depth = DepthState::testAndWrite(CompareFunc::Less);
        const render::PipelineHandle pipeline = gfx_.createPipeline(desc);
        render::PassDesc pass;
        pass.name = "clip";
        pass.color[0] = {color, render::LoadOp::Clear, glm::vec4(0.0f)};
        pass.depth = {depth, render::LoadOp::Clear, 1.0f};
        gfx_.beginPass(pass);
        gfx_.draw(meshDraw(pipeline, render::FlatParams{projection(), glm::vec4(1.0f)}, vb, 3));
        gfx_.endPass();
        const render::Readback c = gfx_.readback(color);
        const render::Readback z = gfx_.readback(depth);

        int covered = 0, checked = 0, failures = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                auto ndc = [&](double dx, double dy) {
                    return castRay(v, 2.0 * (x + 0.5 + dx) / kSize - 1.0, 1.0 - 2.0 * (y + 0.5 + dy) / kSize);
                };
                const RayHit centre = ndc(0, 0);
                constexpr double e = 1.0 / 32.0;
                bool ambiguous = false;
                for (auto [dx, dy] : {std::pair{e, 0.0}, {-e, 0.0}, {0.0, e}, {0.0, -e}})
                    ambiguous = ambiguous || ndc(dx, dy).hit != centre.hit;
                if (ambiguous) continue;
                ++checked;
                const bool drawn = c.at(x, y, 3) != 0.0f;
                std::ostringstream problem;
                if (drawn != centre.hit) {
                    problem << (centre.hit ? "not drawn" : "drawn outside the visible part");
                } else if (centre.hit) {
                    ++covered;
                    for (int k = 0; k < 3; ++k)
                        if (std::fabs(c.at(x, y, k) - centre.barycentric[k]) > 2e-3)
                            problem << "colour " << k << " " << c.at(x, y, k) << " vs " << centre.barycentric[k]
                                    << "; ";
                    // Snapping vertices to 1/256 pixel moves the depth plane by up to half
                    // that times its gradient: allow twice as much.
                    const double step = 1.0 / 256.0;
                    const double tolerance = std::fabs(ndc(step, 0).depth - centre.depth) +
                                             std::fabs(ndc(0, step).depth - centre.depth) + 2e-6;
                    if (std::fabs(z.at(x, y, 0) - centre.depth) > tolerance)
                        problem << "depth " << z.at(x, y, 0) << " vs " << centre.depth << " (tolerance " << tolerance
                                << ")";
                }
                if (!problem.str().empty() && ++failures <= 10)
                    ADD_FAILURE() << what << ": pixel " << x << "," << y << ": " << problem.str();
            }
        }
        EXPECT_GT(covered, 20) << what << ": too little of the triangle is visible to test";
        EXPECT_GT(checked, kSize * kSize * 3 / 4) << what;
    }

private:
    render::TextureHandle target(Format format) {
        render::TextureDesc desc;
        desc.name = "clip";
        desc.width = desc.height = kSize;
        desc.format = format;
        desc.usage = render::UsageRenderTarget;
        return gfx_.createTexture(desc);
    }

    render::Backend& gfx_;
};

TEST_P(ClippingConformance, GroundPlaneBehindTheEye) {
    // The third vertex is behind the camera (clip w < 0).
    const glm::dvec3 v[3] = {{-4, -1, -3}, {4, -1, -3}, {0, -1, 3}};
    ClipRig(gfx()).check(v, "ground plane, w < 0");
}

TEST_P(ClippingConformance, VertexBetweenEyeAndNearPlane) {
    // The third vertex is in front of the eye but nearer than the near plane (0 < w, z < 0).
    const glm::dvec3 v[3] = {{-2, 0.5, -6}, {2, 1.5, -6}, {0.2, -0.3, -0.5}};
    ClipRig(gfx()).check(v, "near plane, z < 0");
}

TEST_P(ClippingConformance, TwoVerticesBehindTheEye) {
    const glm::dvec3 v[3] = {{-0.5, -0.4, -2}, {3, -1, 4}, {-3, 1, 5}};
    ClipRig(gfx()).check(v, "two vertices w < 0");
}

TEST_P(ClippingConformance, BeyondTheFarPlane) {
    const glm::dvec3 v[3] = {{-60, -60, -150}, {60, -20, -150}, {0, 3, -20}};
    ClipRig(gfx()).check(v, "far plane");
}

TEST_P(ClippingConformance, NearAndFarAtOnce) {
    const glm::dvec3 v[3] = {{-1, -0.5, 0.5}, {150, 10, -250}, {-150, 40, -250}};
    ClipRig(gfx()).check(v, "near and far");
}

// Triangles with vertices at +-1e6 in NDC: their hypotenuse x + y = c must split the target
// exactly as the analytic half-plane does, and exactly as the same triangle drawn small (no
// clipping needed). c = 1/16 NDC is exactly representable next to 1e6 in float (one ULP), and
// on a 48-pixel target it puts every pixel centre at least 0.35 pixel from the line.
TEST_P(ClippingConformance, HugeTrianglesMatchSmallOnes) {
    constexpr int kWide = 48;
    const float c = 1.0f / 16.0f;
    struct Case {
        const char* name;
        glm::vec2 v[3];
    };
    const Case cases[] = {
        {"huge 1e6", {{-1e6f, 1e6f + c}, {-1e6f, -1e6f}, {1e6f + c, -1e6f}}},
        {"huge 1e5", {{-1e5f, 1e5f + c}, {-1e5f, -1e5f}, {1e5f + c, -1e5f}}},
        {"small", {{-3.0f, 3.0f + c}, {-3.0f, -3.0f}, {3.0f + c, -3.0f}}},
    };
    for (const Case& k : cases) ASSERT_EQ(double(k.v[0].y) + double(k.v[0].x), double(c)) << k.name;
    const render::TextureHandle color = renderTarget(kWide, kWide, Format::RGBA8_UNORM);
    const render::PipelineHandle pipeline = flatPipeline();
    std::vector<render::Readback> results;
    for (const Case& k : cases) {
        std::vector<render::Vertex> tri(3);
        for (int i = 0; i < 3; ++i) tri[i].position = {k.v[i], 0.5f};
        const render::BufferHandle vb = vertexBuffer(tri);
        pass(color, glm::vec4(0.0f), [&] { drawFlat(pipeline, vb, 3); });
        results.push_back(gfx().readback(color));
        int failures = 0;
        for (int y = 0; y < kWide; ++y)
            for (int x = 0; x < kWide; ++x) {
                const double nx = 2.0 * (x + 0.5) / kWide - 1.0, ny = 1.0 - 2.0 * (y + 0.5) / kWide;
                const float expected = nx + ny < c ? 1.0f : 0.0f;
                if (results.back().at(x, y, 0) != expected && ++failures <= 10)
                    ADD_FAILURE() << k.name << ": pixel " << x << "," << y << " is " << results.back().at(x, y, 0)
                                  << ", the half-plane says " << expected;
            }
    }
    EXPECT_EQ(results[0].values, results[2].values) << "huge and small triangle differ";
    EXPECT_EQ(results[1].values, results[2].values);
}

// Huge triangles (vertices at +-1e6 NDC) whose long edge crosses the target at random
// positions and slopes: every pixel centre more than 1/16 pixel from the exact edge (computed
// in double from the float vertices) is on the right side of it.
TEST_P(ClippingConformance, HugeTrianglesRandomEdges) {
    constexpr int kWide = 64, kHigh = 48;
    const render::TextureHandle color = renderTarget(kWide, kHigh, Format::RGBA8_UNORM);
    const render::PipelineHandle pipeline = flatPipeline();
    std::uint32_t state = 12345;
    auto next = [&] {  // LCG in [0,1)
        state = state * 1664525u + 1013904223u;
        return double(state >> 8) / double(1u << 24);
    };
    int failures = 0;
    for (int i = 0; i < 40; ++i) {
        const double yMid = next() * 1.6 - 0.8, slope = (next() * 2.0 - 1.0) * 1.5, span = i % 2 ? 1e6 : 3e5;
        const glm::vec2 a(float(-span), float(yMid - slope * span)), b(float(span), float(yMid + slope * span));
        const glm::vec2 apex(0.0f, i % 4 < 2 ? float(-span) * 3.0f : float(span) * 3.0f);
        std::vector<render::Vertex> tri(3);
        tri[0].position = {a, 0.5f};
        tri[1].position = {b, 0.5f};
        tri[2].position = {apex, 0.5f};
        const render::BufferHandle vb = vertexBuffer(tri);
        pass(color, glm::vec4(0.0f), [&] { drawFlat(pipeline, vb, 3); });
        const render::Readback r = gfx().readback(color);
        gfx().destroy(vb);
        // Signed distance in pixels of pixel centres from the edge a-b; the apex side is inside.
        const glm::dvec2 pa((double(a.x) + 1) * kWide / 2, (1 - double(a.y)) * kHigh / 2);
        const glm::dvec2 pb((double(b.x) + 1) * kWide / 2, (1 - double(b.y)) * kHigh / 2);
        const glm::dvec2 papex((double(apex.x) + 1) * kWide / 2, (1 - double(apex.y)) * kHigh / 2);
        const glm::dvec2 dir = glm::normalize(pb - pa);
        auto side = [&](glm::dvec2 p) { return (p - pa).x * dir.y - (p - pa).y * dir.x; };
        const double apexSide = side(papex) > 0 ? 1.0 : -1.0;
        for (int y = 0; y < kHigh; ++y)
            for (int x = 0; x < kWide; ++x) {
                const double d = side({x + 0.5, y + 0.5}) * apexSide;
                if (std::fabs(d) < 1.0 / 16.0) continue;
                const float expected = d > 0 ? 1.0f : 0.0f;
                if (r.at(x, y, 0) != expected && ++failures <= 10)
                    ADD_FAILURE() << "edge " << i << " (span " << span << "): pixel " << x << "," << y << " at " << d
                                  << " px from the edge is " << r.at(x, y, 0);
            }
    }
}

// A huge triangle covering the whole target is clipped into a polygon of several triangles
// whose shared edges cross the screen: with additive blending every pixel is hit once.
TEST_P(ClippingConformance, HugeCoveringTriangleHitsEveryPixelOnce) {
    constexpr int kWide = 40, kHigh = 24;
    const render::TextureHandle color = renderTarget(kWide, kHigh, Format::RGBA8_UNORM);
    BlendState additive;
    additive.enabled = true;
    additive.srcRgb = additive.dstRgb = additive.srcAlpha = additive.dstAlpha = BlendFactor::One;
    const render::PipelineHandle pipeline = flatPipeline(additive);
    const std::vector<glm::vec3> triangles[] = {
        {{-1e6f, -1e6f, 0.5f}, {1e6f, -0.9e6f, 0.5f}, {0.3f, 1e6f, 0.5f}},
        {{-3e5f, 0.37f, 0.5f}, {2e6f, -1.2e6f, 0.5f}, {1.1e6f, 2.7e6f, 0.5f}},
        {{0.0f, -5e5f, 0.5f}, {1e6f, 1e6f, 0.5f}, {-1e6f, 1e6f, 0.5f}},
    };
    for (const auto& positions : triangles) {
        std::vector<render::Vertex> tri(3);
        for (int i = 0; i < 3; ++i) tri[i].position = positions[i];
        const render::BufferHandle vb = vertexBuffer(tri);
        pass(color, glm::vec4(0.0f), [&] { drawFlat(pipeline, vb, 3, glm::vec4(1.0f / 255.0f)); });
        const render::Readback r = gfx().readback(color);
        int failures = 0;
        for (int y = 0; y < kHigh; ++y)
            for (int x = 0; x < kWide; ++x)
                if (std::lround(r.at(x, y, 0) * 255.0f) != 1 && ++failures <= 10)
                    ADD_FAILURE() << "pixel " << x << "," << y << " hit " << std::lround(r.at(x, y, 0) * 255.0f)
                                  << " times";
    }
}

// Degenerate (zero area before or after snapping), non-finite and wholly invisible
// triangles change nothing, cost no crash, and are counted as dropped; a valid triangle
// in the same draw still renders.
TEST_P(ClippingConformance, DegenerateAndNonFiniteTrianglesAreDropped) {
    const float nan = std::nanf(""), inf = INFINITY;
    const std::vector<glm::vec3> bad = {
        {-0.5f, -0.5f, 0.5f},  {0.0f, 0.0f, 0.5f},          {0.5f, 0.5f, 0.5f},   // collinear
        {-0.5f, -0.5f, 0.5f},  {-0.5f, -0.5f, 0.5f},        {0.5f, 0.2f, 0.5f},   // two vertices equal
        {0.1f, 0.1f, 0.5f},    {0.1f, 0.1f, 0.5f},          {0.1f, 0.1f, 0.5f},   // a point
        {-0.5f, -0.5f, 0.5f},  {0.5f, -0.5f + 1e-6f, 0.5f}, {0.5f, -0.5f, 0.5f},  // zero area once snapped
        {nan, -0.5f, 0.5f},    {0.5f, -0.5f, 0.5f},         {0.0f, 0.5f, 0.5f},   // NaN x
        {-0.5f, -0.5f, 0.5f},  {0.5f, inf, 0.5f},           {0.0f, 0.5f, 0.5f},   // infinite y
        {-0.5f, -0.5f, nan},   {0.5f, -0.5f, 0.5f},         {0.0f, 0.5f, 0.5f},   // NaN z
        {-0.5f, -0.5f, 2.0f},  {0.5f, -0.5f, 3.0f},         {0.0f, 0.5f, 1.5f},   // beyond the far plane
        {-0.5f, -0.5f, -1.0f}, {0.5f, -0.5f, -0.2f},        {0.0f, 0.5f, -3.0f},  // in front of the near plane
        {3.0f, 3.0f, 0.5f},    {5.0f, 3.0f, 0.5f},          {4.0f, 5.0f, 0.5f},   // off screen
        {3e7f, 3e7f, 0.5f},    {5e7f, 3e7f, 0.5f},          {4e7f, 5e7f, 0.5f},   // far outside any guard band
    };
    const std::size_t badCount = bad.size() / 3;
    std::vector<render::Vertex> vertices;
    for (const glm::vec3& p : bad) {
        render::Vertex v;
        v.position = p;
        vertices.push_back(v);
    }
    // One valid triangle last: the lower-left half of an 8x8 target.
    for (glm::vec3 p : {glm::vec3(-1, 1, 0.5f), glm::vec3(-1, -1, 0.5f), glm::vec3(1, -1, 0.5f)}) {
        render::Vertex v;
        v.position = p;
        vertices.push_back(v);
    }
    const render::TextureHandle color = renderTarget(8, 8, Format::RGBA8_UNORM);
    const render::BufferHandle vb = vertexBuffer(vertices);
    const render::PipelineHandle pipeline = flatPipeline();
    const std::optional<std::uint64_t> before = trianglesDropped();
    // Each bad triangle in a draw of its own, then all of them with the valid one.
    pass(color, glm::vec4(0.0f), [&] {
        for (std::uint32_t i = 0; i < badCount; ++i) drawFlat(pipeline, vb, 3, glm::vec4(1.0f), 3 * i);
    });
    const render::Readback empty = gfx().readback(color);
    for (float v : empty.values) ASSERT_EQ(v, 0.0f) << "a dropped triangle wrote something";
    pass(color, glm::vec4(0.0f), [&] { drawFlat(pipeline, vb, std::uint32_t(vertices.size())); });
    const render::Readback r = gfx().readback(color);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            EXPECT_EQ(r.at(x, y, 0), x < y ? 1.0f : (x > y ? 0.0f : r.at(x, y, 0))) << x << "," << y;
    EXPECT_EQ(r.at(0, 7, 0), 1.0f);
    if (before) {
        const std::uint64_t dropped = *trianglesDropped() - *before;
        EXPECT_EQ(dropped, 2 * badCount) << "every bad triangle counted as dropped, twice (two passes)";
    }
}

// A triangle with a vertex exactly on the w = 0 plane (and the other two visible) is clipped,
// not divided by zero.
TEST_P(ClippingConformance, VertexOnTheEyePlane) {
    const glm::dvec3 v[3] = {{-2, -1, -4}, {2, -1, -4}, {0, -1, 0}};
    ClipRig(gfx()).check(v, "vertex at w = 0");
}

}  // namespace
}  // namespace ssam::test
