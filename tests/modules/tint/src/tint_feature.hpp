// SPDX-License-Identifier: MIT
#pragma once
// The tint as a living-scene feature: one full-screen pass "tint" that multiplies the frame's
// colour (not its alpha) by a constant. Feature::addDrawPass makes it one graph pass.
#include <glm/glm.hpp>

#include "engine/render/owned.hpp"
#include "engine/scene/frame_feature.hpp"

namespace tint {

class TintFeature final : public engine::scene::Feature {
public:
    TintFeature(engine::render::Backend& backend, const glm::vec3& color);

    std::string_view name() const override { return "tint"; }
    // One pass, "tint", every frame.
    engine::render::ColorDepth addPasses(engine::render::FrameGraph& graph, const engine::scene::FeatureFrame& frame,
                                         const engine::render::ColorDepth& targets) override;

private:
    void draw(const engine::scene::FeatureFrame& frame);
    engine::render::Backend& backend_;
    glm::vec3 color_;
    // Owned: a pipeline that fails to be made leaves no program behind.
    engine::render::Owned<engine::render::ProgramHandle> program_;
    engine::render::Owned<engine::render::PipelineHandle> pipeline_;
};

}  // namespace tint
