// SPDX-License-Identifier: MIT
#include "bench_frame.hpp"

#include "engine/render/frame_graph.hpp"
#include "engine/render/frame_graph/side_effect_pass.hpp"
#include "engine/render/pass_scope.hpp"

namespace bench {

using namespace engine::render;

namespace {
// The racer's sky and sun (game/src/frame_renderer.cpp), so frames look like the demo's.
const glm::vec4 kSky{0.55f, 0.70f, 0.88f, 1.0f};
const DirectionalLight kSun{{0.45f, 0.80f, 0.35f}, {1.05f, 0.98f, 0.88f}, {0.32f, 0.36f, 0.42f}};
// The view's draw lists, each plant at the level of detail the camera picks (when it picks).
engine::scene::DrawLists extractView(BenchScene& scene, const BenchCamera& camera) {
    if (camera.focalPixels > 0.0f)
        engine::scene::selectLevelsOfDetail(scene.registry(), scene.library(),
                                            {camera.eye, camera.focalPixels, 0.1f, camera.crossfade});
    return engine::scene::extractDrawLists(scene.registry(), scene.library(), camera.viewProj, camera.eye);
}
}  // namespace

ViewUpload::ViewUpload(Backend& backend, BenchScene& scene, const BenchCamera& camera)
    : backend_(backend), camera_(camera), lists_(extractView(scene, camera)), foliage_(backend) {
    for (const engine::scene::DrawBatch& b : lists_.opaque) {
        const auto bytes = std::as_bytes(std::span(b.instances));
        opaqueInstances_.push_back(
            backend.createBuffer({"opaque instances", BufferKind::Instance, bytes.size()}, bytes));
    }
    draws_ = foliage_.upload(lists_, scene.library());
}

ViewUpload::~ViewUpload() {
    for (BufferHandle b : opaqueInstances_) backend_.destroy(b);
}

transparency::FoliageFrame ViewUpload::foliageFrame(const glm::mat4& viewProj) const {
    transparency::FoliageFrame frame;
    frame.viewProj = viewProj;
    frame.eye = camera_.eye;
    frame.light = kSun;
    frame.draws = draws_;
    frame.movingOpaque = foliage_.movingOpaque();  // the car's motion copies, when it moves
    return frame;
}

std::size_t ViewUpload::foliageInstances() const {
    std::size_t n = 0;
    for (const auto& d : draws_) n += d.batch.instanceCount;
    return n;
}

FrameDrawer::FrameDrawer(Backend& backend, const engine::scene::MeshLibrary& library)
    : backend_(backend), library_(library), transients_(backend) {
    for (bool doubleSided : {false, true}) {
        PipelineDesc p;
        p.name = doubleSided ? "opaque (two-sided)" : "opaque";
        p.program = ProgramKind::OpaqueLit;
        p.depth = DepthState::testAndWrite(kDepthFunc);
        p.raster.cull = doubleSided ? CullMode::None : CullMode::Back;
        (doubleSided ? twoSided_ : culled_) = backend.createPipeline(p);
    }
}

FrameDrawer::~FrameDrawer() {
    backend_.destroy(culled_);
    backend_.destroy(twoSided_);
}

void FrameDrawer::draw(engine::render::FrameTargets& targets, transparency::Technique* technique,
                       const ViewUpload& view, std::uint64_t frameIndex, bool cut) {
    // Temporal techniques move the projection by a sub-pixel jitter, opaque pass and foliage alike.
    const glm::mat4 viewProj =
        technique ? transparency::jitteredViewProj(view.camera().viewProj, technique->projectionJitter(frameIndex),
                                                   targets.desc().width, targets.desc().height)
                  : view.camera().viewProj;
    FrameGraph graph;
    const FrameTargets::InGraph in = targets.importInto(graph);
    struct Drawn {
        ColorDepth out;
    };
    const ColorDepth drawn =
        graph
            .addPass<Drawn>(
                "opaque",
                [&](FrameGraph::Builder& b, Drawn& d) {
                    d.out = {b.write(in.drawn.color), b.write(in.drawn.depth)};
                },
                [&](const FrameGraph::Resources&, const Drawn&) { drawOpaque(targets, view, viewProj); })
            .out;
    const ColorDepth resolved = in.drawn != in.resolved ? in.resolved : drawn;
    transparency::FoliageFrame foliage = view.foliageFrame(viewProj);
    foliage.frameIndex = frameIndex;
    foliage.cut = cut;
    const ColorDepth frame = technique ? technique->addPasses(graph, targets, drawn, resolved, foliage)
                                       : targets.addResolvePass(graph, drawn, resolved);
    addSideEffectPass(graph, "present", frame);
    graph.execute(transients_.allocator());
    transients_.endFrame();
    backend_.endFrame();  // the frame boundary (Backend::endFrame): Vulkan submits here
}

void FrameDrawer::drawOpaque(engine::render::FrameTargets& targets, const ViewUpload& view, const glm::mat4& viewProj) {
    PassScope scope(backend_, targets.passDesc(kSky));
    const auto& opaque = view.lists().opaque;
    for (std::size_t i = 0; i < opaque.size(); ++i) {
        const engine::scene::MeshPart& part = library_.part(opaque[i].part);
        SurfaceParams s;
        s.viewProj = viewProj;
        s.baseColorFactor = part.material.baseColorFactor;
        s.baseColor = part.material.baseColor;
        s.light = kSun;
        if (part.material.unlit) s.light = unlitLight();
        DrawDesc d;
        d.pipeline = part.material.doubleSided ? twoSided_ : culled_;
        d.params = s;
        d.vertices = part.vertices;
        d.indices = part.indices;
        d.count = part.indexCount;
        d.instances = view.opaqueInstances()[i];
        d.instanceCount = static_cast<std::uint32_t>(opaque[i].instances.size());
        backend_.draw(d);
    }
    scope.end();
}

}  // namespace bench
