// SPDX-License-Identifier: MIT
#include "frame_renderer.hpp"

#include <algorithm>
#include <ostream>

#include "engine/capture/image.hpp"
#include "engine/core/error.hpp"
#include "engine/render/frame_graph.hpp"
#include "engine/render/frame_graph/backend_textures.hpp"
#include "engine/render/frame_graph/side_effect_pass.hpp"
#include "transparency/temporal.hpp"
#include "engine/render/pass_scope.hpp"
#include "compare_view.hpp"
#include "hud_text.hpp"
#include "living_scene.hpp"

namespace racer {

using namespace engine::render;
using engine::scene::DrawBatch;
using engine::scene::MeshPart;

namespace {
constexpr CompareFunc kDepthFunc = CompareFunc::Greater;  // reverse-Z
}  // namespace

FrameRenderer::FrameRenderer(Backend& backend, const engine::scene::MeshLibrary& library,
                             const RendererOptions& options)
    : backend_(backend), library_(library), options_(options), foliage_(backend), instances_(backend),
      transients_(backend), overlay_(backend) {
    options_.techniqueOptions.depthFunc = kDepthFunc;
    setTechnique(options.technique);
    opaqueCulled_ = opaquePipeline(false);
    opaqueTwoSided_ = opaquePipeline(true);
    PipelineDesc water;
    water.name = "water (blend over)";
    water.program = ProgramKind::MaskedLit;  // double-sided lit, straight alpha out
    water.blend[0] = BlendState::alphaOver();
    water.depth = DepthState::testOnly(kDepthFunc);
    water_ = backend.createPipeline(water);
    water.name = "blend over (culled)";  // glTF doubleSided false: back faces culled (§3.9.6)
    water.raster.cull = CullMode::Back;
    waterCulled_ = backend.createPipeline(water);
}

FrameRenderer::~FrameRenderer() {
    compare_.reset();  // its renderer and texture before this one's pipelines
    for (PipelineHandle p : {opaqueCulled_, opaqueTwoSided_, water_, waterCulled_}) backend_.destroy(p);
}

void FrameRenderer::setTechnique(transparency::TechniqueKind kind) {
    // Both made before either is replaced: when one throws, the frame stays as it was.
    std::unique_ptr<transparency::Technique> next =
        transparency::createTechnique(kind, backend_, options_.techniqueOptions);
    ensureOpaqueTargets(options_.width, options_.height, std::max(options_.msaa, next->opaqueSamples()));
    technique_ = std::move(next);
    options_.technique = kind;
}

void FrameRenderer::resize(int width, int height) {
    ensureOpaqueTargets(width, height, opaqueSamples());
    if (compare_) compare_->right().resize(width, height);
}

void FrameRenderer::setCompare(std::optional<transparency::TechniqueKind> right) {
    if (!right) {
        compare_.reset();
        return;
    }
    if (compare_) {
        compare_->right().setTechnique(*right);
        return;
    }
    RendererOptions options = options_;
    options.technique = *right;
    options.captureLayers = false;
    auto next = std::make_unique<CompareView>(backend_, library_, options);
    next->right().setLivingScene(living_);
    compare_ = std::move(next);
}

void FrameRenderer::setLivingScene(LivingScene* living) {
    living_ = living;
    if (compare_) compare_->right().setLivingScene(living);
}

bool FrameRenderer::needsMotionVectors() const {
    return technique_->needsMotionVectors() || (compare_ && compare_->right().needsMotionVectors());
}

std::optional<transparency::TechniqueKind> FrameRenderer::comparedTechnique() const {
    if (!compare_) return std::nullopt;
    return compare_->right().technique();
}

std::vector<hud::PixelRect> FrameRenderer::compareMarks() const {
    return compare_ ? compare_->marks() : std::vector<hud::PixelRect>{};
}

hud::PixelRect FrameRenderer::compareCrop() const { return compare_ ? compare_->crop() : hud::PixelRect{}; }

void FrameRenderer::ensureOpaqueTargets(int width, int height, int samples) {
    if (opaque_ && width == options_.width && height == options_.height && opaque_->desc().samples == samples) return;
    // The new targets are made before the current ones go, so a refused size keeps the frame.
    auto next = std::make_unique<engine::render::FrameTargets>(
        backend_,
        engine::render::FrameTargetsDesc{width, height, samples, Format::RGBA8_SRGB, kDepthFunc, options_.msaaDepth});
    opaque_ = std::move(next);
    options_.width = width;
    options_.height = height;
}

PipelineHandle FrameRenderer::opaquePipeline(bool doubleSided) {
    PipelineDesc p;
    p.name = doubleSided ? "opaque (two-sided)" : "opaque";
    p.program = ProgramKind::OpaqueLit;
    p.depth = DepthState::testAndWrite(kDepthFunc);
    p.raster.cull = doubleSided ? CullMode::None : CullMode::Back;
    return backend_.createPipeline(p);
}

SurfaceParams FrameRenderer::surface(const MeshPart& part, const glm::mat4& viewProj) const {
    SurfaceParams s;
    s.viewProj = viewProj;
    s.baseColorFactor = part.material.baseColorFactor;
    s.baseColor = part.material.baseColor;
    s.light = part.material.unlit ? unlitLight() : options_.sun;
    return s;
}

DrawDesc FrameRenderer::batchDraw(const DrawBatch& batch, PipelineHandle pipeline, DrawParams params) {
    const MeshPart& part = library_.part(batch.part);
    DrawDesc d;
    d.pipeline = pipeline;
    d.params = params;
    d.vertices = engine::scene::vertexBufferOf(batch, part);  // deformed copy (modules/wind) or shared
    d.indices = part.indices;
    d.count = part.indexCount;
    d.instances = instances_.upload("instances", BufferKind::Instance, std::as_bytes(std::span(batch.instances)));
    d.instanceCount = static_cast<std::uint32_t>(batch.instances.size());
    return d;
}

void FrameRenderer::capture(TextureHandle target, const char* name) {
    if (options_.captureLayers) layers_.push_back(engine::capture::captureTarget(backend_, target, name));
}

// The technique's intermediates as layers: `targets`, the graph's transients the capture
// pass read, then those the technique keeps itself. SSAM's mask target packs the MAX mask in
// r and the ADD mask in a (or in a separate RG16F target, r), §3.5.2-3.5.3: they become the
// two one-channel layers mask_max and mask_add, as the README's pictures show them.
void FrameRenderer::captureIntermediates(std::vector<transparency::NamedTarget> targets) {
    if (!options_.captureLayers) return;
    namespace cap = engine::capture;
    for (transparency::NamedTarget& kept : technique_->intermediates()) targets.push_back(std::move(kept));
    auto find = [&](const char* name) -> TextureHandle {
        for (const auto& t : targets)
            if (t.name == name) return t.texture;
        return {};
    };
    const TextureHandle packed = find("mask"), maxMask = find("mask_max"), addMask = find("mask_add");
    if (packed || maxMask) {
        const cap::Image mask = cap::captureTarget(backend_, packed ? packed : maxMask, "mask").image;
        const cap::Image add = addMask ? cap::captureTarget(backend_, addMask, "add").image : cap::Image{};
        cap::CapturedLayer maxLayer{"mask_max",
                                    cap::Image::make(options_.width, options_.height, std::vector<std::string>{"Y"})};
        cap::CapturedLayer addLayer{"mask_add",
                                    cap::Image::make(options_.width, options_.height, std::vector<std::string>{"Y"})};
        for (int y = 0; y < options_.height; ++y)
            for (int x = 0; x < options_.width; ++x) {
                maxLayer.image.at(x, y, 0) = mask.at(x, y, 0);
                addLayer.image.at(x, y, 0) = addMask ? add.at(x, y, 0) : mask.at(x, y, 3);
            }
        layers_.push_back(std::move(maxLayer));
        layers_.push_back(std::move(addLayer));
    }
    for (const auto& t : targets)
        if (t.name != "mask" && t.name != "mask_max" && t.name != "mask_add") capture(t.texture, t.name.c_str());
}

void FrameRenderer::render(const engine::scene::DrawLists& lists, const CameraView& unjittered) {
    // B's frame first, by its own renderer and graph (the compare passes below read it).
    if (compare_) {
        if (cut_) compare_->right().cutHistory();
        compare_->right().render(lists, unjittered);
    }
    // The opaque pass and the technique draw with the technique's jitter (none but for the
    // temporal techniques: the same matrix).
    CameraView camera = unjittered;
    camera.viewProj = transparency::jitteredViewProj(unjittered.viewProj, technique_->projectionJitter(frameIndex_),
                                                     options_.width, options_.height);
    layers_.clear();
    instances_.beginFrame();
    overlay_.beginFrame();
    auto graph = std::make_unique<FrameGraph>();
    if (const std::string lod = lodCountsLine(lists); !lod.empty()) graph->addNote(lod);
    const FrameTargets::InGraph in = opaque_->importInto(*graph);

    // 1. Opaque pass (MSAA when the technique or --msaa asks for it).
    const bool multisampled = in.drawn != in.resolved;
    ColorDepth drawn = addOpaquePass(*graph, in.drawn, lists, camera);
    ColorDepth resolved = multisampled ? in.resolved : drawn;  // single-sampled: the same textures
    if (options_.captureLayers) {
        // The technique resolves again after drawing; resolving here too only costs time
        // when layers are captured.
        struct Data {};
        graph->addPass<Data>(
            "capture opaque",
            [&](FrameGraph::Builder& b, Data&) {
                drawn = {b.read(drawn.color), b.read(drawn.depth)};
                if (multisampled) resolved = {b.write(resolved.color), b.write(resolved.depth)};
                b.sideEffect();
            },
            [this](const FrameGraph::Resources&, const Data&) {
                opaque_->resolve();
                capture(opaque_->color(), "opaque");
                capture(opaque_->depth(), "depth");
            });
        if (!multisampled) resolved = drawn;
    }

    // 2. Foliage by the technique: it draws, resolves the frame targets and leaves the
    //    colour and the depth later passes test against in them.
    const transparency::FoliageFrame foliage{
        camera.viewProj, camera.eye, options_.sun,           foliage_.upload(lists, library_),
        frameIndex_,     cut_,       foliage_.movingOpaque()};
    ++frameIndex_;
    cut_ = false;
    ColorDepth frame = technique_->addPasses(*graph, *opaque_, drawn, resolved, foliage);
    if (options_.captureLayers) addCaptureFoliagePass(*graph, frame);

    // 3. The living scene's passes (grass, water, particles, light shafts) onto the colour,
    //    depth-tested against the opaque + foliage depth; without one, BLEND surfaces here.
    const engine::scene::FeatureFrame features{backend_,
                                               library_,
                                               lists,
                                               opaque_->color(),
                                               opaque_->depth(),
                                               options_.width,
                                               options_.height,
                                               unjittered.view,
                                               unjittered.projection,
                                               unjittered.viewProj,
                                               unjittered.eye,
                                               options_.sun,
                                               0.0f,
                                               kDepthFunc};
    frame = living_ ? living_->addPasses(*graph, features, frame) : addBlendPass(*graph, frame, features, unjittered);

    // 4. Side by side: B's right half, the insets and labels over A's frame (compare_view.hpp).
    const int scale = hud::textScaleFor(options_.height);
    int hudTop = 4 * scale;
    if (compare_) {
        frame.color = compare_->addPasses(*graph, frame.color, opaque_->color(), options_.width, options_.height,
                                          transparency::techniqueName(technique()), overlay_);
        hudTop += 24 * scale;  // below the labels
    }

    // 5. The HUD over the finished frame (modules/hud), at its top-left corner.
    hudBox_ = {};
    if (!hudLines_.empty()) {
        hud::OverlayContent hud;
        hud.text.push_back(hud::layoutText(hudLines_, glm::ivec2(4 * scale, hudTop), scale));
        hudBox_ = hud.text.back().box;
        frame.color = overlay_.addPass(*graph, "hud", frame.color, opaque_->color(), options_.width, options_.height,
                                       std::move(hud));
    }

    // 6. The frame leaves the graph: presented by the caller, captured here.
    addSideEffectPass(*graph, "present", frame, [this] { capture(opaque_->color(), "result"); });

    graph->execute(transients_.allocator());
    transients_.endFrame();
    backend_.endFrame();  // the frame boundary (Backend::endFrame): Vulkan submits here
    lastGraph_ = std::move(graph);
}

// --capture-layers: a side-effect pass after the technique that reads the frame and the
// technique's transients, so the graph keeps them alive until it has captured them.
void FrameRenderer::addCaptureFoliagePass(FrameGraph& graph, const ColorDepth& frame) {
    struct Data {
        std::vector<transparency::GraphTarget> kept;
    };
    graph.addPass<Data>(
        "capture foliage",
        [&](FrameGraph::Builder& b, Data& d) {
            b.read(frame.color);
            b.read(frame.depth);
            for (const transparency::GraphTarget& t : technique_->graphIntermediates())
                d.kept.push_back({t.layer, b.read(t.texture)});
            b.sideEffect();
        },
        [this](const FrameGraph::Resources& r, const Data& d) {
            std::vector<transparency::NamedTarget> targets;
            for (const transparency::GraphTarget& t : d.kept)
                targets.push_back({t.layer, toTextureHandle(r.get(t.texture))});
            captureIntermediates(std::move(targets));
            capture(opaque_->depth(), "foliage_depth");
        });
}

std::uint64_t FrameRenderer::peakTransientBytes() const {
    return lastGraph_ ? lastGraph_->peakTransientBytes(backendTextureBytes) : 0;
}

ColorDepth FrameRenderer::addOpaquePass(FrameGraph& graph, const ColorDepth& targets,
                                        const engine::scene::DrawLists& lists, const CameraView& camera) {
    struct Data {
        ColorDepth out;
    };
    return graph
        .addPass<Data>(
            "opaque",
            [&](FrameGraph::Builder& b, Data& d) {
                d.out = {b.write(targets.color), b.write(targets.depth)};
            },
            [this, &lists, viewProj = camera.viewProj](const FrameGraph::Resources&, const Data&) {
                PassScope scope(backend_, opaque_->passDesc(options_.background));
                for (const DrawBatch& b : lists.opaque) {
                    const MeshPart& part = library_.part(b.part);
                    backend_.draw(batchDraw(b, part.material.doubleSided ? opaqueTwoSided_ : opaqueCulled_,
                                            surface(part, viewProj)));
                }
                scope.end();
            })
        .out;
}

ColorDepth FrameRenderer::addBlendPass(FrameGraph& graph, const ColorDepth& targets,
                                       const engine::scene::FeatureFrame& frame, const CameraView& camera) {
    struct Data {
        ColorDepth out;
    };
    const engine::scene::DrawLists& lists = frame.lists;
    return graph
        .addPass<Data>(
            "water",
            [&](FrameGraph::Builder& b, Data& d) {
                d.out = {b.write(b.read(targets.color)), b.read(targets.depth)};
                if (lists.blend.empty()) b.markEmpty();
            },
            [this, &lists, viewProj = camera.viewProj](const FrameGraph::Resources&, const Data&) {
                PassDesc pass;
                pass.name = "water";
                pass.color[0] = {opaque_->color(), LoadOp::Load};
                pass.depth = {opaque_->depth(), LoadOp::Load};
                PassScope passScope(backend_, pass);
                for (const DrawBatch& b : lists.blend) {
                    const MeshPart& part = library_.part(b.part);
                    backend_.draw(
                        batchDraw(b, part.material.doubleSided ? water_ : waterCulled_, surface(part, viewProj)));
                }
                passScope.end();
            })
        .out;
}

void FrameRenderer::dumpGraph(std::ostream& out) const {
    if (!lastGraph_) throw engine::Error("no frame rendered yet: nothing to dump");
    lastGraph_->dumpGraphviz(out, backendTextureBytes);
}

}  // namespace racer
