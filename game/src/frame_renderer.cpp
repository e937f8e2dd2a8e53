#include "frame_renderer.hpp"

#include "engine/capture/image.hpp"

namespace racer {

using namespace engine::render;
using engine::scene::DrawBatch;
using engine::scene::MeshPart;

const char* techniqueName(Technique technique) {
    switch (technique) {
        case Technique::Ssam: return "ssam";
        case Technique::AlphaTest: return "alpha-test";
    }
    return "?";
}

namespace {
const glm::vec4 kSky{0.55f, 0.70f, 0.88f, 1.0f};
const DirectionalLight kSun{{0.45f, 0.80f, 0.35f}, {1.05f, 0.98f, 0.88f}, {0.32f, 0.36f, 0.42f}};
constexpr CompareFunc kDepthFunc = CompareFunc::Greater;  // reverse-Z
}  // namespace

FrameRenderer::FrameRenderer(Backend& backend, const engine::scene::MeshLibrary& library, const RendererOptions& options)
    : backend_(backend), library_(library), options_(options),
      opaque_(backend, {options.width, options.height, options.opaqueSamples, Format::RGBA8_SRGB, kDepthFunc}) {
    options_.ssam.depthFunc = kDepthFunc;
    if (options.technique == Technique::Ssam) ssam_ = std::make_unique<ssam::ScreenSpaceAlphaMask>(backend, options_.ssam);
    opaqueCulled_ = opaquePipeline(false);
    opaqueTwoSided_ = opaquePipeline(true);
    PipelineDesc water;
    water.name = "water (blend over)";
    water.program = ProgramKind::FoliageColor;  // double-sided lit, straight alpha out
    water.blend[0] = BlendState::alphaOver();
    water.depth = DepthState::testOnly(kDepthFunc);
    water_ = backend.createPipeline(water);
}

FrameRenderer::~FrameRenderer() {
    for (BufferHandle b : frameBuffers_) backend_.destroy(b);
    for (auto& [cutoff, p] : alphaTested_) backend_.destroy(p);
    for (PipelineHandle p : {opaqueCulled_, opaqueTwoSided_, water_}) backend_.destroy(p);
}

PipelineHandle FrameRenderer::opaquePipeline(bool doubleSided) {
    PipelineDesc p;
    p.name = doubleSided ? "opaque (two-sided)" : "opaque";
    p.program = ProgramKind::OpaqueLit;
    p.depth = DepthState::testAndWrite(kDepthFunc);
    p.raster.cull = doubleSided ? CullMode::None : CullMode::Back;
    return backend_.createPipeline(p);
}

PipelineHandle FrameRenderer::alphaTestPipeline(float cutoff) {
    auto [it, fresh] = alphaTested_.try_emplace(cutoff);
    if (fresh) {
        PipelineDesc p;
        p.name = "foliage alpha test";
        p.program = ProgramKind::FoliageColor;
        p.depth = DepthState::testAndWrite(kDepthFunc);
        p.alphaTest = AlphaTest::discardBelow(cutoff);
        // The frame's alpha stays the opaque 1: the texture's alpha only decides coverage.
        p.blend[0].writeMask = WriteRGB;
        it->second = backend_.createPipeline(p);
    }
    return it->second;
}

BufferHandle FrameRenderer::uploadInstances(const DrawBatch& batch) {
    const auto bytes = std::as_bytes(std::span(batch.instances));
    frameBuffers_.push_back(backend_.createBuffer({"instances", BufferKind::Instance, bytes.size()}, bytes));
    return frameBuffers_.back();
}

DrawDesc FrameRenderer::batchDraw(const DrawBatch& batch, PipelineHandle pipeline, ProgramParams params) {
    const MeshPart& part = library_.part(batch.part);
    DrawDesc d;
    d.pipeline = pipeline;
    d.params = std::move(params);
    d.vertices = part.vertices;
    d.indices = part.indices;
    d.count = part.indexCount;
    d.instances = uploadInstances(batch);
    d.instanceCount = static_cast<std::uint32_t>(batch.instances.size());
    return d;
}

void FrameRenderer::capture(TextureHandle target, const char* name) {
    if (options_.captureLayers) layers_.push_back(engine::capture::captureTarget(backend_, target, name));
}

void FrameRenderer::captureMask() {
    if (!options_.captureLayers || !ssam_ || !ssam_->intermediates().mask) return;
    namespace cap = engine::capture;
    const ssam::Intermediates t = ssam_->intermediates();
    const cap::CapturedLayer mask = cap::captureTarget(backend_, t.mask, "mask");
    cap::CapturedLayer maxLayer{"mask_max", cap::Image::make(options_.width, options_.height, std::vector<std::string>{"Y"})};
    cap::CapturedLayer addLayer{"mask_add", cap::Image::make(options_.width, options_.height, std::vector<std::string>{"Y"})};
    const cap::Image add = t.maskAdd ? cap::captureTarget(backend_, t.maskAdd, "add").image : cap::Image{};
    for (int y = 0; y < options_.height; ++y)
        for (int x = 0; x < options_.width; ++x) {
            maxLayer.image.at(x, y, 0) = mask.image.at(x, y, 0);
            addLayer.image.at(x, y, 0) = t.maskAdd ? add.at(x, y, 0) : mask.image.at(x, y, 3);
        }
    layers_.push_back(std::move(maxLayer));
    layers_.push_back(std::move(addLayer));
    capture(t.foliage, "foliage");
}

void FrameRenderer::render(const engine::scene::DrawLists& lists, const CameraView& camera) {
    for (BufferHandle b : frameBuffers_) backend_.destroy(b);
    frameBuffers_.clear();
    layers_.clear();

    auto surface = [&](const MeshPart& part) {
        SurfaceParams s;
        s.viewProj = camera.viewProj;
        s.baseColorFactor = part.material.baseColorFactor;
        s.baseColor = part.material.baseColor;
        s.light = kSun;
        if (part.material.unlit) s.light = {kSun.towardLight, glm::vec3(0.0f), glm::vec3(1.0f)};
        return s;
    };

    // 1. Opaque pass; with plain alpha testing the foliage is drawn here too.
    backend_.beginPass(opaque_.passDesc(kSky));
    for (const DrawBatch& b : lists.opaque) {
        const MeshPart& part = library_.part(b.part);
        backend_.draw(batchDraw(b, part.material.doubleSided ? opaqueTwoSided_ : opaqueCulled_, surface(part)));
    }
    if (options_.technique == Technique::AlphaTest)
        for (const DrawBatch& b : lists.mask) {
            const MeshPart& part = library_.part(b.part);
            backend_.draw(batchDraw(b, alphaTestPipeline(part.material.alphaCutoff), surface(part)));
        }
    backend_.endPass();
    opaque_.resolve();
    capture(opaque_.color(), "opaque");
    capture(opaque_.depth(), "depth");

    // 2. SSAM: mask, colour (writes foliage depth), composite.
    if (ssam_) {
        std::vector<ssam::FoliageBatch> foliage;
        for (const DrawBatch& b : lists.mask) {
            const MeshPart& part = library_.part(b.part);
            ssam::FoliageBatch f;
            f.vertices = part.vertices;
            f.indices = part.indices;
            f.count = part.indexCount;
            f.instances = uploadInstances(b);
            f.instanceCount = static_cast<std::uint32_t>(b.instances.size());
            f.baseColor = part.material.baseColor;
            f.baseColorFactor = part.material.baseColorFactor;
            f.worldBounds = {b.worldBounds.min, b.worldBounds.max};
            foliage.push_back(f);
        }
        ssam_->render({opaque_.color(), opaque_.depth()}, {camera.viewProj, kSun, foliage});
        captureMask();
        capture(opaque_.depth(), "foliage_depth");
    }

    // 3. BLEND surfaces back to front, tested against the opaque + foliage depth.
    if (!lists.blend.empty()) {
        PassDesc pass;
        pass.name = "water";
        pass.color[0] = {opaque_.color(), LoadOp::Load};
        pass.depth = {opaque_.depth(), LoadOp::Load};
        backend_.beginPass(pass);
        for (const DrawBatch& b : lists.blend) backend_.draw(batchDraw(b, water_, surface(library_.part(b.part))));
        backend_.endPass();
    }
    capture(opaque_.color(), "result");
}

}  // namespace racer
