// SPDX-License-Identifier: MIT
#pragma once
// A card that moves under a still camera, drawn by a temporal technique frame after frame,
// with or without motion vectors (MaskedBatch::motionVertices: previous minus current position
// in each vertex's normal): the scene of the motion-vector tests on soft, GL and Vulkan. The
// card is foliage (the technique draws it), or an opaque box seen face on (Surface::Opaque: the
// opaque pass draws it with OpaqueLit, and it moves as FoliageFrame::movingOpaque, as the car does).
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "engine/render/backend.hpp"
#include "engine/render/frame_targets.hpp"
#include "run_technique.hpp"
#include "transparency/create_technique.hpp"
#include "transparency/temporal.hpp"

namespace transparency::testing {

class MovingCardScene {
public:
    static constexpr int kSize = 64;
    static constexpr float kPixel = 2.0f / kSize;  // one pixel in NDC, exact

    enum class Surface { Foliage, Opaque };

    // `alpha`: the card's vertex alpha (1 for an opaque box); its colour is a ramp in red across
    // it, so that a history fetched from the wrong place is seen inside the card as well as
    // along its edges.
    MovingCardScene(engine::render::Backend& backend, TechniqueKind kind, float alpha, bool motionVectors,
                    Surface surface = Surface::Foliage)
        : backend_(backend), technique_(createTechnique(kind, backend, options(motionVectors))),
          opaque_(backend, {kSize, kSize, technique_->opaqueSamples(), engine::render::Format::RGBA32F,
                            engine::render::CompareFunc::Less}),
          alpha_(surface == Surface::Opaque ? 1.0f : alpha), surface_(surface) {
        using namespace engine::render;
        if (surface_ == Surface::Opaque) {
            PipelineDesc p;
            p.name = "moving box";
            p.program = ProgramKind::OpaqueLit;
            p.depth = DepthState::testAndWrite(CompareFunc::Less);
            boxPipeline_ = backend.createPipeline(p);
            draw_.alphaCutoff = 0.0f;
        }
        const std::vector<Vertex> rest = vertices(0.0f, 0.0f);
        const auto bytes = std::as_bytes(std::span(rest));
        vertices_ = backend.createBuffer({"card", BufferKind::Vertex, bytes.size()}, bytes);
        motion_ = backend.createBuffer({"card motion", BufferKind::Vertex, bytes.size()}, bytes);
        draw_.batch.vertices = vertices_;
        draw_.batch.count = 6;
    }
    ~MovingCardScene() {
        if (boxPipeline_) backend_.destroy(boxPipeline_);
        backend_.destroy(vertices_);
        backend_.destroy(motion_);
    }
    MovingCardScene(const MovingCardScene&) = delete;
    MovingCardScene& operator=(const MovingCardScene&) = delete;

    // Frame `index` with the card moved `offset` in NDC x from its rest place (the camera is the
    // identity, jittered as the technique asks); returns the frame's colour. The card's motion is
    // given from its second frame on.
    engine::render::Readback frame(std::uint64_t index, float offset) {
        using namespace engine::render;
        const std::vector<Vertex> moved = vertices(offset, 0.0f), motion = vertices(offset, previous_ - offset);
        backend_.updateBuffer(vertices_, 0, std::as_bytes(std::span(moved)));
        draw_.batch.motionVertices = {};
        if (index > 0) {
            backend_.updateBuffer(motion_, 0, std::as_bytes(std::span(motion)));
            draw_.batch.motionVertices = motion_;
        }
        previous_ = offset;
        draw_.batch.worldBounds = {{-0.5f + offset, -0.5f, 0.5f}, {0.5f + offset, 0.5f, 0.5f}};
        draw_.meshBounds = draw_.batch.worldBounds;
        FoliageFrame f;
        f.viewProj = jitteredViewProj(glm::mat4(1.0f), technique_->projectionJitter(index), kSize, kSize);
        f.light = unlitLight();
        backend_.beginPass(opaque_.passDesc({0.1f, 0.2f, 0.3f, 1.0f}));
        if (surface_ == Surface::Opaque) {
            DrawDesc box;
            box.pipeline = boxPipeline_;
            SurfaceParams params;
            params.viewProj = f.viewProj;
            params.light = f.light;
            box.params = params;
            box.vertices = vertices_;
            box.count = 6;
            backend_.draw(box);
        }
        backend_.endPass();
        (surface_ == Surface::Opaque ? f.movingOpaque : f.draws) = std::span(&draw_, 1);
        f.frameIndex = index;
        test_support::runTechnique(backend_, *technique_, opaque_, f);
        return backend_.readback(opaque_.color());
    }

private:
    static TechniqueOptions options(bool motionVectors) {
        TechniqueOptions o;
        o.temporal.motionVectors = motionVectors;
        return o;
    }
    // The card moved by `offset`, each normal (motion, 0, 0). Edges a quarter pixel off the
    // pixel grid (0.5 - 1/128 in NDC), so that the jitter moves them across pixel centres.
    std::vector<engine::render::Vertex> vertices(float offset, float motion) const {
        constexpr float e = 0.5f - 1.0f / 128.0f;
        const glm::vec2 c[6] = {{-e, -e}, {e, -e}, {e, e}, {-e, -e}, {e, e}, {-e, e}};
        std::vector<engine::render::Vertex> v;
        for (const glm::vec2& p : c) {
            engine::render::Vertex x;
            x.position = {p.x + offset, p.y, 0.5f};
            x.normal = {motion, 0.0f, 0.0f};
            x.uv = (p + 0.5f) * 0.77f;
            x.color = {p.x + 0.5f, 1.0f, 1.0f, alpha_};
            v.push_back(x);
        }
        return v;
    }

    engine::render::Backend& backend_;
    std::unique_ptr<Technique> technique_;
    engine::render::FrameTargets opaque_;
    float alpha_;
    Surface surface_;
    engine::render::PipelineHandle boxPipeline_;
    engine::render::BufferHandle vertices_, motion_;
    FoliageDraw draw_;
    float previous_ = 0.0f;
};

}  // namespace transparency::testing
