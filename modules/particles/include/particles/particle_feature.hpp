// SPDX-License-Identifier: MIT
#pragma once
// The particles module as a living-scene feature.
//   system "particles" (phase::simulation): ParticleSimulation::update with the frame's dt
//   pass "particles": camera-facing quads into an RGBA16F layer cleared to 0, full or half
//       resolution, the Particle program (particle_programs.hpp) with BlendState::premultipliedOver(): alpha-blended
//       dust and additive spray in one target, a = src.a + dst.a(1 - src.a) ([Turánszki 2017]);
//       soft against the opaque + foliage depth (so a tree in front hides them, §3.7)
//   pass "particles composite": the LayerComposite program, the layer over the frame with
//       the premultiplied blend; a half-resolution layer is upsampled by nearest depth.
// No live particle in view: neither pass runs. The layer is the frame graph's transient,
// created by the "particles" pass and gone after it.
#include <memory>

#include "engine/render/frame_buffer_pool.hpp"
#include "engine/render/owned.hpp"
#include "engine/scene/frame_feature.hpp"
#include "particles/particle_simulation.hpp"

namespace particles {

class ParticleFeature final : public engine::scene::Feature {
public:
    ParticleFeature(engine::render::Backend& backend, const ParticleOptions& options = {}, std::uint64_t seed = 1);
    ~ParticleFeature() override;

    std::string_view name() const override { return "particles"; }
    void registerSystems(engine::ecs::Scheduler& scheduler) override;
    void beginFrame(const engine::scene::SimulationFrame& frame) override { dt_ = frame.dt; }
    // One pass, which also creates the layer as a transient; empty when no particle is in view.
    engine::render::ColorDepth addPasses(engine::render::FrameGraph& graph, const engine::scene::FeatureFrame& frame,
                                         const engine::render::ColorDepth& targets) override;

    ParticleSimulation& simulation() { return simulation_; }
    // The layer's version the last addPasses() wrote, for a later pass of the same graph to
    // read (a capture); invalid when no particle was in view.
    engine::render::FrameGraphTexture graphLayer() const { return graphLayer_; }
    std::size_t drawnLastFrame() const { return drawn_; }

private:
    bool prepare(const engine::scene::FeatureFrame& frame);  // the quads of the particles in view
    void drawInto(const engine::scene::FeatureFrame& frame, engine::render::TextureHandle layer);
    int layerStride() const { return simulation_.options().halfResolution ? 2 : 1; }

    engine::render::Backend& backend_;
    ParticleSimulation simulation_;
    float dt_ = 0.0f;

    // Owned: a create that throws in the constructor leaves nothing made before it behind.
    engine::render::Owned<engine::render::ProgramHandle> particleProgram_, compositeProgram_;  // particle_programs.hpp
    engine::render::Owned<engine::render::PipelineHandle> particlePipeline_, compositePipeline_;
    engine::render::FrameBufferPool buffers_;  // the quads, reused frame after frame
    // What prepare() found: camera-facing quads and the screen region they touch.
    std::vector<engine::render::Vertex> vertices_;
    std::vector<std::uint32_t> indices_;
    engine::render::Rect region_;
    engine::render::FrameGraphTexture graphLayer_;
    std::size_t drawn_ = 0;
};

}  // namespace particles
