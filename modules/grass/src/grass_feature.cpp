// SPDX-License-Identifier: MIT
#include "grass/grass_feature.hpp"

#include <string>

#include "engine/core/error.hpp"
#include "engine/render/pass_scope.hpp"

namespace grass {

using namespace engine::render;

GrassFeature::GrassFeature(Backend& backend, std::vector<Tuft> tufts, const GrassOptions& options)
    : backend_(backend), options_(options), tufts_(std::move(tufts)), instances_(backend) {
    validate(options_);
    if (tufts_.size() > options_.maxTufts)
        throw engine::Error("grass: " + std::to_string(tufts_.size()) + " tufts exceed the limit of " +
                            std::to_string(options_.maxTufts));
    std::vector<Vertex> v;
    std::vector<std::uint32_t> i;
    buildCard(options_, v, i);
    // Owned: whatever a later create throws, what was made before is destroyed with it.
    vertices_ =
        Owned<BufferHandle>(backend, backend.createBuffer({"grass card", BufferKind::Vertex, v.size() * sizeof(Vertex)},
                                                          std::as_bytes(std::span(v))));
    indices_ = Owned<BufferHandle>(
        backend,
        backend.createBuffer({"grass card indices", BufferKind::Index, i.size() * 4}, std::as_bytes(std::span(i))));
    indexCount_ = std::uint32_t(i.size());
    constexpr int kW = 64, kH = 32;
    const std::vector<std::uint8_t> texels = bladeTexels(kW, kH, 17);
    TextureDesc desc;
    desc.name = "grass blades";
    desc.width = kW;
    desc.height = kH;
    desc.format = Format::RGBA8_SRGB;
    const TextureData data{{std::as_bytes(std::span(texels))}};
    blades_ = Owned<TextureHandle>(backend, backend.createTexture(desc, &data));
}

GrassFeature::~GrassFeature() = default;

PipelineHandle GrassFeature::pipeline(CompareFunc depthFunc) {
    if (pipeline_.get() && pipelineDepthFunc_ == depthFunc) return pipeline_;
    pipeline_.reset();  // a create that throws below leaves no stale handle behind
    PipelineDesc p;
    p.name = "grass (alpha tested)";
    p.program = ProgramKind::MaskedLit;
    p.depth = DepthState::testAndWrite(depthFunc);
    p.alphaTest = AlphaTest::discardBelow(options_.alphaReference);
    p.blend[0].writeMask = WriteRGB;  // the frame's alpha stays; the card's alpha only cuts it out
    pipeline_ = Owned<PipelineHandle>(backend_, backend_.createPipeline(p));
    pipelineDepthFunc_ = depthFunc;
    return pipeline_;
}

engine::render::ColorDepth GrassFeature::addPasses(engine::render::FrameGraph& graph,
                                                   const engine::scene::FeatureFrame& frame,
                                                   const engine::render::ColorDepth& targets) {
    return addDrawPass(graph, frame, targets, !prepare(frame), DepthUse::TestAndWrite,
                       [this](const engine::scene::FeatureFrame& f) { draw(f); });
}

bool GrassFeature::prepare(const engine::scene::FeatureFrame& frame) {
    instances_.beginFrame();
    visible_ = visibleTufts(tufts_, options_, frame.eye, frame.viewProj, frame.time);
    drawn_ = visible_.size();
    return !visible_.empty();  // nothing near: no pass
}

void GrassFeature::draw(const engine::scene::FeatureFrame& frame) {
    const BufferHandle instances =
        instances_.upload("grass tufts", BufferKind::Instance, std::as_bytes(std::span(visible_)));
    const PipelineHandle cards = pipeline(frame.depthFunc);
    PassDesc pass;
    pass.name = "grass";
    pass.color[0] = {frame.color, LoadOp::Load};
    pass.depth = {frame.depth, LoadOp::Load};
    PassScope passScope(backend_, pass);
    const SurfaceParams surface{.viewProj = frame.viewProj,
                                .baseColor = {blades_, {Filter::Bilinear, AddressMode::Wrap, AddressMode::Clamp}},
                                .light = frame.sun};
    backend_.draw({.pipeline = cards,
                   .params = surface,
                   .vertices = vertices_,
                   .indices = indices_,
                   .count = indexCount_,
                   .instances = instances,
                   .instanceCount = std::uint32_t(visible_.size()),
                   .scissor = std::nullopt});
    passScope.end();
}

}  // namespace grass
