// SPDX-License-Identifier: MIT
#pragma once
// A tiny frame for technique tests: soft backend, 16x16 opaque targets cleared to a known
// colour, and foliage made of NDC quads (tests/support/quad_scene.hpp) with known colours,
// alphas and depths, lit with ambient 1 only so each fragment's colour is its vertex colour.
#include <memory>
#include <vector>

#include "engine/render/frame_targets.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "quad_scene.hpp"
#include "run_technique.hpp"
#include "transparency/create_technique.hpp"

namespace transparency::testing {

using namespace engine::render;
using ssam::testing::Quad;

inline constexpr int kSize = 16;
inline const glm::vec4 kOpaqueColor{0.2f, 0.4f, 0.6f, 1.0f};

struct TechniqueFrame {
    Backend& backend;
    engine::render::FrameTargets opaque;
    std::unique_ptr<ssam::testing::QuadBatches> quads;
    std::vector<FoliageDraw> draws;

    TechniqueFrame(Backend& b, int samples, const std::vector<Quad>& foliage, Format format = Format::RGBA32F)
        : backend(b), opaque(b, {kSize, kSize, samples, format, CompareFunc::Less}) {
        quads = std::make_unique<ssam::testing::QuadBatches>(backend, foliage);
        for (std::size_t i = 0; i < foliage.size(); ++i) {
            FoliageDraw d;
            d.batch = quads->batches[i];
            d.meshBounds = d.batch.worldBounds;  // identity instance
            draws.push_back(d);
        }
    }

    // The opaque pass: clear to kOpaqueColor, draw `opaqueQuads` (flat colour) with depth.
    void opaquePass(const std::vector<Quad>& opaqueQuads = {}) {
        PipelineDesc p;
        p.name = "opaque flat";
        p.depth = DepthState::testAndWrite();
        const PipelineHandle pipeline = backend.createPipeline(p);
        ssam::testing::QuadBatches geometry(backend, opaqueQuads);
        backend.beginPass(opaque.passDesc(kOpaqueColor));
        geometry.drawFlat(pipeline);
        backend.endPass();
        backend.destroy(pipeline);
    }

    FoliageFrame frame() const {
        FoliageFrame f;
        f.light = unlitLight();
        f.draws = draws;
        return f;
    }

    // opaque pass, then the technique's passes in a one-off frame graph; returns the final colour.
    Readback run(Technique& technique, const std::vector<Quad>& opaqueQuads = {}) {
        opaquePass(opaqueQuads);
        test_support::runTechnique(backend, technique, opaque, frame());
        return backend.readback(opaque.color());
    }
};

// Straight-alpha "over" of (color, alpha) onto dst ([Hargreaves 2009] "conventional").
inline glm::vec3 over(const glm::vec4& src, const glm::vec3& dst) {
    return glm::vec3(src) * src.a + dst * (1.0f - src.a);
}

inline glm::vec3 rgbAt(const Readback& r, int x, int y) { return {r.at(x, y, 0), r.at(x, y, 1), r.at(x, y, 2)}; }

}  // namespace transparency::testing
