// SPDX-License-Identifier: MIT
#include "tint_feature.hpp"

#include "engine/render/pass_scope.hpp"
#include "tint/tint_program.hpp"

namespace tint {

using namespace engine::render;

TintFeature::TintFeature(Backend& backend, const glm::vec3& color)
    : backend_(backend), color_(color), program_(backend, backend.createProgram(tintProgram())) {
    PipelineDesc p;
    p.name = "tint (multiply)";
    p.program = program_.get();
    // colour = frame * tint; the frame's alpha is left as it is.
    p.blend[0] = {true,         BlendFactor::Zero, BlendFactor::SrcColor,
                  BlendOp::Add, BlendFactor::Zero, BlendFactor::One,
                  BlendOp::Add, WriteRGB};
    pipeline_ = Owned<PipelineHandle>(backend, backend.createPipeline(p));
}

engine::render::ColorDepth TintFeature::addPasses(engine::render::FrameGraph& graph,
                                                  const engine::scene::FeatureFrame& frame,
                                                  const engine::render::ColorDepth& targets) {
    return addDrawPass(graph, frame, targets, /*empty=*/false, DepthUse::Test,
                       [this](const engine::scene::FeatureFrame& f) { draw(f); });
}

void TintFeature::draw(const engine::scene::FeatureFrame& frame) {
    PassDesc pass;
    pass.name = "tint";
    pass.color[0] = {frame.color, LoadOp::Load};
    PassScope passScope(backend_, pass);
    DrawDesc d;
    d.pipeline = pipeline_;
    d.params = TintParams{color_};
    backend_.draw(d);
    passScope.end();
}

}  // namespace tint
