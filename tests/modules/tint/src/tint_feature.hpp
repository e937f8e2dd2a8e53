// SPDX-License-Identifier: MIT
#pragma once
// The tint as a living-scene feature: one full-screen pass "tint" that multiplies the frame's
// colour (not its alpha) by a constant. The base class's addPasses makes it one graph pass.
#include <glm/glm.hpp>

#include "engine/render/owned.hpp"
#include "engine/scene/frame_feature.hpp"

namespace tint {

class TintFeature final : public engine::scene::Feature {
public:
    TintFeature(engine::render::Backend& backend, const glm::vec3& color);

    std::string_view name() const override { return "tint"; }
    bool prepare(const engine::scene::FeatureFrame&) override { return true; }
    void draw(const engine::scene::FeatureFrame& frame) override;

private:
    engine::render::Backend& backend_;
    glm::vec3 color_;
    // Owned: a pipeline that fails to be made leaves no program behind.
    engine::render::Owned<engine::render::ProgramHandle> program_;
    engine::render::Owned<engine::render::PipelineHandle> pipeline_;
};

}  // namespace tint
