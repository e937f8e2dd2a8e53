// SPDX-License-Identifier: MIT
#pragma once
// The grass module as a living-scene feature: the "grass" pass draws every visible tuft
// (GrassOptions::drawDistance) as one instanced draw of an alpha-tested card, depth-tested
// against and writing into the opaque + foliage depth, so a tree in front hides the grass
// behind it and the passes after (water, particles) see the grass ([Hathaway 2010] §3.7).
#include <vector>

#include "engine/render/frame_buffer_pool.hpp"
#include "engine/render/owned.hpp"
#include "engine/scene/frame_feature.hpp"
#include "grass/grass_field.hpp"

namespace grass {

class GrassFeature final : public engine::scene::Feature {
public:
    // Throws engine::Error for bad options or more tufts than options.maxTufts.
    GrassFeature(engine::render::Backend& backend, std::vector<Tuft> tufts, const GrassOptions& options = {});
    ~GrassFeature() override;

    std::string_view name() const override { return "grass"; }
    // One pass, "grass", that writes the depth too (later passes see the grass); empty when
    // no tuft is in view.
    engine::render::ColorDepth addPasses(engine::render::FrameGraph& graph, const engine::scene::FeatureFrame& frame,
                                         const engine::render::ColorDepth& targets) override;

    std::size_t tufts() const { return tufts_.size(); }
    std::size_t drawnLastFrame() const { return drawn_; }

private:
    bool prepare(const engine::scene::FeatureFrame& frame);  // the visible tufts, uploaded
    void draw(const engine::scene::FeatureFrame& frame);
    engine::render::PipelineHandle pipeline(engine::render::CompareFunc depthFunc);

    engine::render::Backend& backend_;
    GrassOptions options_;
    std::vector<Tuft> tufts_;
    engine::render::Owned<engine::render::BufferHandle> vertices_, indices_;
    engine::render::FrameBufferPool instances_;
    std::vector<engine::render::Instance> visible_;  // prepare()'s tufts, drawn by draw()
    std::uint32_t indexCount_ = 0;
    engine::render::Owned<engine::render::TextureHandle> blades_;
    engine::render::Owned<engine::render::PipelineHandle> pipeline_;
    engine::render::CompareFunc pipelineDepthFunc_ = engine::render::CompareFunc::Less;
    std::size_t drawn_ = 0;
};

}  // namespace grass
