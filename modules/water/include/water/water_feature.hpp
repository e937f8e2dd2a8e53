// SPDX-License-Identifier: MIT
#pragma once
// The water module: a "water ripples" system (phase::deformation) gives every pool in view
// its own copy of its mesh with animated normals (VertexOverride), and the "water" pass
// draws the frame's BLEND batches back to front, straight-alpha "over" ([Hargreaves 2009]), lit
// double-sided, depth-tested against the opaque + foliage depth without writing it
// ([Hathaway 2010] §3.7: foliage in front hides the water, foliage behind does not).
#include <map>
#include <vector>

#include "engine/render/frame_buffer_pool.hpp"
#include "engine/render/owned.hpp"
#include "engine/scene/frame_feature.hpp"
#include "water/ripples.hpp"

namespace water {

class WaterFeature final : public engine::scene::Feature {
public:
    explicit WaterFeature(const engine::scene::MeshLibrary& library, const Ripples& ripples = {});
    ~WaterFeature() override;

    std::string_view name() const override { return "water"; }
    void registerSystems(engine::ecs::Scheduler& scheduler) override;
    void beginFrame(const engine::scene::SimulationFrame& frame) override { frame_ = frame; }
    // One pass, "water", empty when nothing is in view.
    engine::render::ColorDepth addPasses(engine::render::FrameGraph& graph, const engine::scene::FeatureFrame& frame,
                                         const engine::render::ColorDepth& targets) override;

    void setRipples(const Ripples& ripples);  // validated
    // The ripple system on its own (what the scheduler runs).
    void updateRipples(engine::ecs::Registry& registry);
    std::size_t ripplingSurfaces() const { return surfaces_.size(); }

private:
    bool prepare(const engine::scene::FeatureFrame& frame);  // whether a BLEND batch is in view
    void draw(const engine::scene::FeatureFrame& frame);
    struct Surface {
        std::vector<engine::render::Owned<engine::render::BufferHandle>> buffers;  // per part slot; null: not water
        std::vector<std::vector<engine::render::Vertex>> vertices;
    };
    engine::render::PipelineHandle pipeline(engine::render::CompareFunc depthFunc, bool doubleSided);
    void releaseSurface(engine::ecs::Registry& registry, engine::ecs::Entity e, Surface& s);

    const engine::scene::MeshLibrary& library_;
    Ripples ripples_;
    engine::scene::SimulationFrame frame_;
    std::map<engine::ecs::Entity, Surface> surfaces_;
    std::map<std::pair<engine::render::CompareFunc, bool>, engine::render::Owned<engine::render::PipelineHandle>>
        pipelines_;
    engine::render::FrameBufferPool frameInstances_;  // instance data, reused frame after frame
};

}  // namespace water
