// SPDX-License-Identifier: MIT
#pragma once
// The wind module as a living-scene feature: one system, "wind", in phase::deformation.
// It draws no pass of its own: deformed plants reach the frame through extraction
// (VertexOverride), drawn by the foliage technique like any other foliage.
#include <memory>

#include "engine/scene/frame_feature.hpp"
#include "wind/wind_system.hpp"

namespace wind {

class WindFeature final : public engine::scene::Feature {
public:
    // Adds a default Wind entity when the registry has none, and Sway to every plant.
    WindFeature(engine::ecs::Registry& registry, const engine::scene::MeshLibrary& library, std::uint32_t seed = 1);

    std::string_view name() const override { return "wind"; }
    void registerSystems(engine::ecs::Scheduler& scheduler) override;
    void beginFrame(const engine::scene::SimulationFrame& frame) override;
    // Wind only deforms (its system); it adds no pass to the frame.
    engine::render::ColorDepth addPasses(engine::render::FrameGraph&, const engine::scene::FeatureFrame&,
                                         const engine::render::ColorDepth& targets) override {
        return targets;
    }

    WindSystem& system() { return system_; }

private:
    WindSystem system_;
};

}  // namespace wind
