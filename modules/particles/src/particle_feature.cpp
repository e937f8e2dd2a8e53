// SPDX-License-Identifier: MIT
#include "particles/particle_feature.hpp"

#include <cmath>

#include "engine/render/frame_graph.hpp"
#include "engine/render/frame_graph/backend_textures.hpp"
#include "engine/render/pass_scope.hpp"
#include "engine/scene/bounds.hpp"
#include "particles/particle_programs.hpp"
#include "engine/render/screen_bounds.hpp"

namespace particles {

using namespace engine::render;

ParticleFeature::ParticleFeature(Backend& backend, const ParticleOptions& options, std::uint64_t seed)
    : backend_(backend), simulation_(options, seed), buffers_(backend) {
    particleProgram_ = Owned<ProgramHandle>(backend, backend.createProgram(particleProgram()));
    compositeProgram_ = Owned<ProgramHandle>(backend, backend.createProgram(layerCompositeProgram()));
    PipelineDesc p;
    p.name = "particles (premultiplied)";
    p.program = particleProgram_.get();
    p.blend[0] = BlendState::premultipliedOver();  // [Turánszki 2017]: one layer for alpha and additive
    particlePipeline_ = Owned<PipelineHandle>(backend, backend.createPipeline(p));
    p.name = "particles composite";
    p.program = compositeProgram_.get();
    compositePipeline_ = Owned<PipelineHandle>(backend, backend.createPipeline(p));
}

ParticleFeature::~ParticleFeature() = default;

void ParticleFeature::registerSystems(engine::ecs::Scheduler& scheduler) {
    scheduler.add(
        engine::ecs::phase::simulation, "particles",
        [this](engine::ecs::Registry& registry, engine::ecs::CommandBuffer&) { simulation_.update(registry, dt_); });
}

namespace {

// The layer for a frame of width x height at 1/stride of its resolution (rounded up).
TextureDesc layerDesc(int width, int height, int stride) {
    TextureDesc desc = renderTargetDesc("particle layer", (width + stride - 1) / stride, (height + stride - 1) / stride,
                                        Format::RGBA16F);  // HDR: additive spray may exceed 1 ([Turánszki 2017])
    desc.alpha = AlphaMode::Premultiplied;
    return desc;
}

}  // namespace

ColorDepth ParticleFeature::addPasses(FrameGraph& graph, const engine::scene::FeatureFrame& frame,
                                      const ColorDepth& targets) {
    struct Data {
        ColorDepth out;
        FrameGraphTexture layer;
    };
    const bool empty = !prepare(frame);
    const Data& data = graph.addPass<Data>(
        std::string(name()),
        [&](FrameGraph::Builder& b, Data& d) {
            d.out = {b.write(b.read(targets.color)), b.read(targets.depth)};
            if (empty) return b.markEmpty();
            const TextureDesc layer = layerDesc(frame.width, frame.height, layerStride());
            d.layer = b.write(b.create(layer.name, graphDescOf(layer)));
        },
        [this, frame](const FrameGraph::Resources& r, const Data& d) {
            drawInto(frame, toTextureHandle(r.get(d.layer)));
        });
    graphLayer_ = data.layer;
    return data.out;
}

bool ParticleFeature::prepare(const engine::scene::FeatureFrame& frame) {
    buffers_.beginFrame();
    drawn_ = 0;
    vertices_.clear();
    indices_.clear();
    const std::vector<Particle>& live = simulation_.particles();
    if (live.empty()) return false;

    // Camera-facing quads; the view distance rides in normal.x, "additive" in normal.y
    // (program.hpp ParticleParams). Particles behind the eye are skipped.
    const glm::vec3 right(frame.view[0][0], frame.view[1][0], frame.view[2][0]);
    const glm::vec3 up(frame.view[0][1], frame.view[1][1], frame.view[2][1]);
    std::vector<Vertex>& vertices = vertices_;
    std::vector<std::uint32_t>& indices = indices_;
    engine::scene::Aabb bounds;  // of every quad: both passes are scissored to its screen region
    vertices.reserve(live.size() * 4);
    indices.reserve(live.size() * 6);
    for (const Particle& p : live) {
        const float distance = -(frame.view * glm::vec4(p.position, 1.0f)).z;
        const float size = simulation_.sizeOf(p);
        if (!(distance > 0.0f) || !std::isfinite(distance)) continue;
        const float opacity = simulation_.opacityOf(p);  // fades with age, thins along its trail
        const std::uint32_t base = std::uint32_t(vertices.size());
        const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const glm::vec2& c : corners) {
            Vertex v;
            v.position = p.position + (right * c.x + up * c.y) * size;
            v.normal = {distance, p.additive, 0.0f};
            v.uv = c * 0.5f + 0.5f;
            v.color = glm::vec4(glm::vec3(p.color), p.color.a * opacity);
            vertices.push_back(v);
            bounds.add(v.position);
        }
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(base + i);
    }
    const std::optional<Rect> region =
        engine::render::screenBounds({bounds.min, bounds.max}, frame.viewProj, frame.width, frame.height);
    if (vertices.empty() || !region) return false;
    drawn_ = vertices.size() / 4;
    region_ = *region;
    return true;
}

void ParticleFeature::drawInto(const engine::scene::FeatureFrame& frame, TextureHandle layer) {
    const ParticleOptions& o = simulation_.options();
    const Rect& region = region_;
    const int stride = layerStride();
    const BufferHandle vertices = buffers_.upload("particles", BufferKind::Vertex, std::as_bytes(std::span(vertices_)));
    const BufferHandle indices =
        buffers_.upload("particle indices", BufferKind::Index, std::as_bytes(std::span(indices_)));
    const bool greater = frame.depthFunc == CompareFunc::Greater || frame.depthFunc == CompareFunc::GreaterEqual;
    // distance = P[3][2] / (depth + P[2][2]) for the engine's perspective projections.
    const float depthScale = frame.projection[3][2], depthOffset = frame.projection[2][2];

    PassDesc pass;
    pass.name = "particles";
    pass.color[0] = {layer, LoadOp::Clear, glm::vec4(0.0f)};
    PassScope passScope(backend_, pass);
    DrawDesc d;
    d.pipeline = particlePipeline_;
    d.params = ParticleParams{frame.viewProj, frame.depth, stride, depthScale, depthOffset, o.softness, greater};
    d.vertices = vertices;
    d.indices = indices;
    d.count = std::uint32_t(indices_.size());
    const int x0 = region.x / stride, y0 = region.y / stride;
    d.scissor = Rect{x0, y0, (region.x + region.width + stride - 1) / stride - x0 + 1,
                     (region.y + region.height + stride - 1) / stride - y0 + 1};
    backend_.draw(d);
    passScope.end();

    PassDesc composite;
    composite.name = "particles composite";
    composite.color[0] = {frame.color, LoadOp::Load};
    PassScope compositeScope(backend_, composite);
    DrawDesc c;
    c.pipeline = compositePipeline_;
    c.params = LayerCompositeParams{layer, frame.depth, stride, depthScale, depthOffset, greater};
    c.scissor = region;
    backend_.draw(c);
    compositeScope.end();
}

}  // namespace particles
