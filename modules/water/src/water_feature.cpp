// SPDX-License-Identifier: MIT
#include "water/water_feature.hpp"

#include <algorithm>

#include "engine/render/pass_scope.hpp"
#include "engine/scene/components.hpp"

namespace water {

using namespace engine;
using namespace engine::render;

WaterFeature::WaterFeature(const scene::MeshLibrary& library, const Ripples& ripples)
    : library_(library), frameInstances_(library.backend()) {
    setRipples(ripples);
}

WaterFeature::~WaterFeature() = default;

void WaterFeature::setRipples(const Ripples& ripples) {
    validate(ripples);
    ripples_ = ripples;
}

void WaterFeature::registerSystems(ecs::Scheduler& scheduler) {
    scheduler.add(ecs::phase::deformation, "water ripples",
                  [this](ecs::Registry& registry, ecs::CommandBuffer&) { updateRipples(registry); });
}

void WaterFeature::releaseSurface(ecs::Registry& registry, ecs::Entity e, Surface& s) {
    s.buffers.clear();
    if (registry.alive(e) && registry.has<scene::VertexOverride>(e)) registry.remove<scene::VertexOverride>(e);
}

void WaterFeature::updateRipples(ecs::Registry& registry) {
    // Pools in view get rippling normals; the rest keep the shared flat mesh.
    std::vector<std::pair<ecs::Entity, scene::ModelId>> visible;
    registry.view<const scene::Transform, const scene::Renderable>().each(
        [&](ecs::Entity e, const scene::Transform& t, const scene::Renderable& r) {
            bool water = false;
            for (std::uint32_t p : library_.partsOf(r.model))
                water = water || library_.part(p).material.surface == scene::SurfaceClass::Blend;
            if (!water || (registry.has<scene::VertexOverride>(e) && !surfaces_.contains(e))) return;
            if (scene::intersectsViewVolume(library_.bounds(r.model).transformed(t.matrix()), frame_.viewProj))
                visible.emplace_back(e, r.model);
        });
    for (auto it = surfaces_.begin(); it != surfaces_.end();) {
        const bool keep =
            std::any_of(visible.begin(), visible.end(), [&](const auto& v) { return v.first == it->first; });
        if (keep) {
            ++it;
        } else {
            releaseSurface(registry, it->first, it->second);
            it = surfaces_.erase(it);
        }
    }
    for (const auto& [e, model] : visible) {
        const std::vector<std::uint32_t>& parts = library_.partsOf(model);
        auto it = surfaces_.find(e);
        if (it == surfaces_.end()) {
            // Made whole before it is entered: a create that throws leaves no half-made surface.
            Surface made;
            made.buffers.resize(parts.size());
            made.vertices.assign(parts.size(), {});
            for (std::size_t i = 0; i < parts.size(); ++i) {
                const scene::MeshPart& part = library_.part(parts[i]);
                if (part.material.surface != scene::SurfaceClass::Blend) continue;
                made.vertices[i] = library_.vertices(parts[i]);
                const auto bytes = std::as_bytes(std::span(made.vertices[i]));
                made.buffers[i] = Owned<BufferHandle>(
                    library_.backend(), library_.backend().createBuffer(
                                            {part.name + " (ripples)", BufferKind::Vertex, bytes.size()}, bytes));
            }
            it = surfaces_.emplace(e, std::move(made)).first;
        }
        Surface& s = it->second;
        scene::VertexOverride override;
        for (const Owned<BufferHandle>& b : s.buffers) override.buffers.push_back(b.get());
        override.bounds.assign(parts.size(), scene::Aabb{});
        for (std::size_t i = 0; i < parts.size(); ++i) {
            if (!s.buffers[i].get()) continue;
            rippleNormals(library_.vertices(parts[i]), s.vertices[i], ripples_, frame_.time);
            library_.backend().updateBuffer(s.buffers[i], 0, std::as_bytes(std::span(s.vertices[i])));
        }
        if (scene::VertexOverride* existing = registry.tryGet<scene::VertexOverride>(e))
            *existing = std::move(override);
        else registry.add<scene::VertexOverride>(e, std::move(override));
    }
}

PipelineHandle WaterFeature::pipeline(CompareFunc depthFunc, bool doubleSided) {
    // Made before it is entered, so a create that throws leaves no empty entry behind.
    if (const auto it = pipelines_.find({depthFunc, doubleSided}); it != pipelines_.end()) return it->second;
    PipelineDesc p;
    p.name = doubleSided ? "water (blend over)" : "water (blend over, culled)";
    p.raster.cull = doubleSided ? CullMode::None : CullMode::Back;  // glTF doubleSided (§3.9.6)
    p.program = ProgramKind::MaskedLit;                             // double-sided lit, straight alpha out
    p.blend[0] = BlendState::alphaOver();
    p.depth = DepthState::testOnly(depthFunc);
    Owned<PipelineHandle> pipeline(library_.backend(), library_.backend().createPipeline(p));
    return pipelines_.emplace(std::pair{depthFunc, doubleSided}, std::move(pipeline)).first->second;
}

engine::render::ColorDepth WaterFeature::addPasses(engine::render::FrameGraph& graph, const scene::FeatureFrame& frame,
                                                   const engine::render::ColorDepth& targets) {
    return addDrawPass(graph, frame, targets, !prepare(frame), DepthUse::Test,
                       [this](const scene::FeatureFrame& f) { draw(f); });
}

bool WaterFeature::prepare(const scene::FeatureFrame& frame) {
    frameInstances_.beginFrame();
    return !frame.lists.blend.empty();  // no pool in view: no pass
}

void WaterFeature::draw(const scene::FeatureFrame& frame) {
    Backend& backend = frame.backend;
    PassDesc pass;
    pass.name = "water";
    pass.color[0] = {frame.color, LoadOp::Load};
    pass.depth = {frame.depth, LoadOp::Load};
    PassScope passScope(backend, pass);
    for (const scene::DrawBatch& b : frame.lists.blend) {  // already back to front
        const scene::MeshPart& part = frame.library.part(b.part);
        SurfaceParams s;
        s.viewProj = frame.viewProj;
        s.baseColorFactor = part.material.baseColorFactor;
        s.baseColor = part.material.baseColor;
        s.light = frame.sun;
        if (part.material.unlit) s.light = {frame.sun.towardLight, glm::vec3(0.0f), glm::vec3(1.0f)};
        DrawDesc d;
        d.pipeline = pipeline(frame.depthFunc, part.material.doubleSided);
        d.params = s;
        d.vertices = scene::vertexBufferOf(b, part);
        d.indices = part.indices;
        d.count = part.indexCount;
        d.instances =
            frameInstances_.upload("water instances", BufferKind::Instance, std::as_bytes(std::span(b.instances)));
        d.instanceCount = std::uint32_t(b.instances.size());
        backend.draw(d);
    }
    passScope.end();
}

}  // namespace water
