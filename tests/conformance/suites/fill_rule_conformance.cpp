// SPDX-License-Identifier: MIT
// Fill rule: meshes of adjacent triangles (fans and jittered grids, both windings mixed,
// vertices at random sub-pixel positions and exactly on pixel centres) drawn with additive
// blending must cover every sample inside exactly once: no double hits on shared edges or
// vertices, no holes.
//
// Single-sample: RGBA8 cleared to 0, ONE/ONE of 1/255, so each pixel holds its hit count.
// Multisampled: RGBA32F, RGB = ONE/ONE ADD of 1 (hits per sample), alpha = ONE/ZERO of 1
// (1 once hit at all). After the resolve, R = mean(hits) and A = mean(hit at least once),
// and R == A exactly when no sample was hit twice; A == 1 when none was missed.
#include <cmath>
#include <cstdint>
#include <random>

#include "../backend_fixture.hpp"

namespace ssam::test {
namespace {

struct Mesh {
    std::vector<render::Vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<glm::dvec2> outline;  // boundary polygon in pixels (empty: the whole target)
};

// Uniform in [0,1), the same on every platform (unlike std::uniform_real_distribution).
struct Random {
    std::mt19937 engine;
    explicit Random(std::uint32_t seed) : engine(seed) {}
    double next() { return double(engine() >> 5) / double(1u << 27); }
    double range(double lo, double hi) { return lo + (hi - lo) * next(); }
    bool coin() { return (engine() & 1u) != 0; }
};

// A fan around `centre` whose rim is a star-shaped polygon with random radii and angles.
Mesh fan(int width, int height, glm::dvec2 centre, int spokes, double radius, std::uint32_t seed) {
    Random random(seed);
    Mesh m;
    m.vertices.push_back(pixelVertex(width, height, centre.x, centre.y));
    const double step = 2.0 * M_PI / spokes;
    for (int i = 0; i < spokes; ++i) {
        const double angle = (i + random.range(-0.3, 0.3)) * step;
        const double r = radius * random.range(0.6, 1.0);
        const glm::dvec2 p = centre + r * glm::dvec2(std::cos(angle), std::sin(angle));
        m.outline.push_back(p);
        m.vertices.push_back(pixelVertex(width, height, p.x, p.y));
    }
    for (int i = 0; i < spokes; ++i) {
        std::uint32_t a = 1 + i, b = 1 + (i + 1) % spokes;
        if (random.coin()) std::swap(a, b);  // both windings
        m.indices.insert(m.indices.end(), {0u, a, b});
    }
    return m;
}

// A grid of cells x cells quads over the whole target, each split along a random diagonal
// with a random winding. Interior vertices are jittered by up to `jitter` of a cell; with
// `onCentres` they are instead snapped to pixel centres (so edges run through samples).
Mesh grid(int width, int height, int cells, double jitter, bool onCentres, std::uint32_t seed) {
    Random random(seed);
    Mesh m;
    const double cw = double(width) / cells, ch = double(height) / cells;
    for (int j = 0; j <= cells; ++j) {
        for (int i = 0; i <= cells; ++i) {
            double x = i * cw, y = j * ch;
            if (i > 0 && i < cells) x += onCentres ? 0.0 : random.range(-jitter, jitter) * cw;
            if (j > 0 && j < cells) y += onCentres ? 0.0 : random.range(-jitter, jitter) * ch;
            if (onCentres) {
                if (i > 0 && i < cells) x = std::floor(x) + 0.5 + double(int(random.next() * 3) - 1);
                if (j > 0 && j < cells) y = std::floor(y) + 0.5 + double(int(random.next() * 3) - 1);
            }
            m.vertices.push_back(pixelVertex(width, height, x, y));
        }
    }
    auto at = [&](int i, int j) { return std::uint32_t(j * (cells + 1) + i); };
    for (int j = 0; j < cells; ++j) {
        for (int i = 0; i < cells; ++i) {
            const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            std::uint32_t t[2][3];
            if (random.coin()) {
                t[0][0] = a, t[0][1] = b, t[0][2] = c, t[1][0] = a, t[1][1] = c, t[1][2] = d;
            } else {
                t[0][0] = a, t[0][1] = b, t[0][2] = d, t[1][0] = b, t[1][1] = c, t[1][2] = d;
            }
            for (auto& tri : t) {
                if (random.coin()) std::swap(tri[1], tri[2]);
                m.indices.insert(m.indices.end(), {tri[0], tri[1], tri[2]});
            }
        }
    }
    return m;
}

// Inside/outside of the outline for a point, and its distance to the outline.
bool insideOutline(const std::vector<glm::dvec2>& poly, glm::dvec2 p) {
    bool inside = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
            p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
            inside = !inside;
    }
    return inside;
}

double distanceToOutline(const std::vector<glm::dvec2>& poly, glm::dvec2 p) {
    double best = INFINITY;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const glm::dvec2 e = poly[i] - poly[j];
        const double t = glm::clamp(glm::dot(p - poly[j], e) / glm::dot(e, e), 0.0, 1.0);
        best = std::min(best, glm::length(p - (poly[j] + t * e)));
    }
    return best;
}

// -1: pixel straddles the outline (within `margin` pixels); 0: outside; 1: inside.
int classify(const Mesh& m, int x, int y, double margin) {
    if (m.outline.empty()) return 1;
    const glm::dvec2 centre(x + 0.5, y + 0.5);
    if (distanceToOutline(m.outline, centre) < margin) return -1;
    return insideOutline(m.outline, centre) ? 1 : 0;
}

class FillRuleRig {
public:
    void checkSingleSample(render::Backend& gfx, int width, int height, const Mesh& m, const std::string& what) {
        BlendState additive;
        additive.enabled = true;
        additive.srcRgb = additive.dstRgb = additive.srcAlpha = additive.dstAlpha = BlendFactor::One;
        const render::TextureHandle target = makeTarget(gfx, width, height, Format::RGBA8_UNORM, 1);
        draw(gfx, target, m, additive, glm::vec4(1.0f / 255.0f));
        const render::Readback r = gfx.readback(target);
        int inside = 0, failures = 0;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const long hits = std::lround(r.at(x, y, 0) * 255.0f);
                const int expected = classify(m, x, y, 1.0 / 64.0);
                inside += expected == 1;
                const bool ok = expected == -1 ? hits <= 1 : hits == expected;
                if (!ok && ++failures <= 10)
                    ADD_FAILURE() << what << ": pixel " << x << "," << y << " hit " << hits << " times, expected "
                                  << (expected == -1 ? "0 or 1" : std::to_string(expected));
            }
        }
        EXPECT_GT(inside, width * height / 8) << what;
        gfx.destroy(target);
    }

    void checkMultisample(render::Backend& gfx, int width, int height, int samples, const Mesh& m,
                          const std::string& what) {
        BlendState counting;
        counting.enabled = true;
        counting.srcRgb = counting.dstRgb = BlendFactor::One;
        counting.srcAlpha = BlendFactor::One;
        counting.dstAlpha = BlendFactor::Zero;
        const render::TextureHandle target = makeTarget(gfx, width, height, Format::RGBA32F, samples);
        draw(gfx, target, m, counting, glm::vec4(1.0f));
        render::TextureHandle single = target;
        if (samples > 1) {
            single = makeTarget(gfx, width, height, Format::RGBA32F, 1);
            gfx.resolve({target, single});
        }
        const render::Readback r = gfx.readback(single);
        int failures = 0;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const float meanHits = r.at(x, y, 0), meanCovered = r.at(x, y, 3);
                // Every sample within a pixel of the outline is strictly inside or outside.
                const int expected = classify(m, x, y, 1.0);
                bool ok = meanHits == meanCovered;  // no sample hit twice
                if (expected >= 0) ok = ok && meanCovered == float(expected);
                if (!ok && ++failures <= 10)
                    ADD_FAILURE() << what << " " << samples << "x: pixel " << x << "," << y << " mean hits " << meanHits
                                  << ", covered fraction " << meanCovered
                                  << (expected == 1   ? " (inside)"
                                      : expected == 0 ? " (outside)"
                                                      : " (edge)");
            }
        }
        gfx.destroy(target);
        if (single != target) gfx.destroy(single);
    }

private:
    render::TextureHandle makeTarget(render::Backend& gfx, int width, int height, Format format, int samples) {
        return gfx.createTexture(render::renderTargetDesc("fill", width, height, format, samples));
    }

    void draw(render::Backend& gfx, render::TextureHandle target, const Mesh& m, const BlendState& blend,
              glm::vec4 color) {
        render::PipelineDesc desc;
        desc.name = "fill";
        desc.blend[0] = blend;
        const render::PipelineHandle pipeline = gfx.createPipeline(desc);
        const render::BufferHandle vb = gfx.createBuffer(
            {"mesh", render::BufferKind::Vertex, m.vertices.size() * sizeof(render::Vertex)}, bytesOf(m.vertices));
        const render::BufferHandle ib = gfx.createBuffer(
            {"mesh", render::BufferKind::Index, m.indices.size() * sizeof(std::uint32_t)}, bytesOf(m.indices));
        render::PassDesc pass;
        pass.name = "fill";
        pass.color[0] = {target, render::LoadOp::Clear, glm::vec4(0.0f)};
        gfx.beginPass(pass);
        render::DrawDesc d;
        d.pipeline = pipeline;
        d.params = render::FlatParams{glm::mat4(1.0f), color};
        d.vertices = vb;
        d.indices = ib;
        d.count = std::uint32_t(m.indices.size());
        gfx.draw(d);
        gfx.endPass();
        gfx.destroy(vb);
        gfx.destroy(ib);
        gfx.destroy(pipeline);
    }
};

TEST_P(FillRuleConformance, FanAroundPixelCentre) {
    FillRuleRig rig;
    for (std::uint32_t seed = 1; seed <= 4; ++seed)
        rig.checkSingleSample(gfx(), 48, 40, fan(48, 40, {24.5, 20.5}, 37, 18.0, seed),
                              "fan on centre seed " + std::to_string(seed));
}

TEST_P(FillRuleConformance, FanAroundSubpixelPoint) {
    FillRuleRig rig;
    for (std::uint32_t seed = 1; seed <= 4; ++seed)
        rig.checkSingleSample(gfx(), 48, 40, fan(48, 40, {23.37, 19.81}, 29, 18.0, seed),
                              "fan off centre seed " + std::to_string(seed));
}

TEST_P(FillRuleConformance, JitteredGrid) {
    FillRuleRig rig;
    for (std::uint32_t seed = 1; seed <= 4; ++seed)
        rig.checkSingleSample(gfx(), 67, 45, grid(67, 45, 9, 0.4, false, seed), "grid seed " + std::to_string(seed));
}

TEST_P(FillRuleConformance, GridOnPixelCentres) {
    FillRuleRig rig;
    for (std::uint32_t seed = 1; seed <= 4; ++seed)
        rig.checkSingleSample(gfx(), 64, 48, grid(64, 48, 8, 0.0, true, seed),
                              "centred grid seed " + std::to_string(seed));
}

// A regular grid with axis-aligned edges exactly on pixel boundaries and diagonals through
// pixel centres: the most tie-heavy case.
TEST_P(FillRuleConformance, RegularGrid) {
    FillRuleRig rig;
    rig.checkSingleSample(gfx(), 32, 32, grid(32, 32, 8, 0.0, false, 7), "regular grid");
}

TEST_P(FillRuleConformance, MultisampledMeshes) {
    FillRuleRig rig;
    for (int samples : {4, 8}) {
        for (std::uint32_t seed = 1; seed <= 2; ++seed) {
            rig.checkMultisample(gfx(), 48, 40, samples, fan(48, 40, {24.5, 20.5}, 37, 18.0, seed), "fan on centre");
            rig.checkMultisample(gfx(), 48, 40, samples, fan(48, 40, {23.37, 19.81}, 29, 18.0, seed), "fan off centre");
            rig.checkMultisample(gfx(), 67, 45, samples, grid(67, 45, 9, 0.4, false, seed), "jittered grid");
            rig.checkMultisample(gfx(), 64, 48, samples, grid(64, 48, 8, 0.0, true, seed), "centred grid");
        }
        rig.checkMultisample(gfx(), 32, 32, samples, grid(32, 32, 8, 0.0, false, 7), "regular grid");
    }
}

// The float single-sample variant of the counting check (no UNORM rounding involved).
TEST_P(FillRuleConformance, SingleSampleCountingFloat) {
    FillRuleRig rig;
    rig.checkMultisample(gfx(), 48, 40, 1, fan(48, 40, {24.5, 20.5}, 37, 18.0, 3), "fan on centre");
    rig.checkMultisample(gfx(), 67, 45, 1, grid(67, 45, 9, 0.4, false, 3), "jittered grid");
}

}  // namespace
}  // namespace ssam::test
