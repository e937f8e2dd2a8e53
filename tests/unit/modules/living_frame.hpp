// SPDX-License-Identifier: MIT
#pragma once
// A whole living-scene frame for module tests, on any backend: extraction, the opaque pass,
// then in a one-off frame graph (tests/support/run_graph.hpp) SSAM's passes (whose colour
// pass writes the foliage depth) and each feature's passes in order, as the racer runs them.
// Reverse-Z, as the racer.
#include <functional>
#include <memory>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/core/ecs/registry.hpp"
#include "engine/render/frame_targets.hpp"
#include "engine/render/projection.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/components.hpp"
#include "engine/scene/draw_lists.hpp"
#include "engine/scene/frame_feature.hpp"
#include "run_feature.hpp"
#include "ssam/frame_graph_passes.hpp"
#include "ssam/ssam.hpp"

namespace living::testing {

inline const engine::render::DirectionalLight kSun{{0.45f, 0.80f, 0.35f}, {1.0f, 1.0f, 1.0f}, {0.3f, 0.3f, 0.3f}};

struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 0.0f};
    glm::vec3 target{0.0f, 0.0f, 1.0f};
    float fovY = 1.0f;
    glm::mat4 view() const { return glm::lookAt(eye, target, glm::vec3(0, 1, 0)); }
    glm::mat4 projection(float aspect) const {
        return engine::render::perspectiveReverseZ(fovY, aspect, 0.1f, 30000.0f);
    }
};

// One frame; returns the colour (and keeps the targets for inspection).
struct LivingFrame {
    engine::render::Backend& backend;
    const engine::scene::MeshLibrary& library;
    int width, height;
    engine::render::FrameTargets opaque{
        backend, {width, height, 1, engine::render::Format::RGBA8_UNORM, engine::render::CompareFunc::Greater}};
    std::unique_ptr<ssam::ScreenSpaceAlphaMask> ssam = [this] {
        ssam::Settings c;
        c.depthTest = ssam::DepthTest::Greater;
        return std::make_unique<ssam::ScreenSpaceAlphaMask>(backend, c);
    }();
    engine::render::PipelineHandle opaquePipeline = [this] {
        engine::render::PipelineDesc p;
        p.name = "opaque";
        p.program = engine::render::ProgramKind::OpaqueLit;
        p.depth = engine::render::DepthState::testAndWrite(engine::render::CompareFunc::Greater);
        return backend.createPipeline(p);
    }();

    // Textures of the graph (a feature's transients) to read back after the features' passes,
    // into readBacks; set before render().
    std::function<std::vector<engine::render::FrameGraphTexture>()> readBackAfterFeatures;
    std::vector<engine::render::Readback> readBacks;

    LivingFrame(engine::render::Backend& b, const engine::scene::MeshLibrary& l, int w, int h)
        : backend(b), library(l), width(w), height(h) {}
    ~LivingFrame() { backend.destroy(opaquePipeline); }

    engine::render::Readback render(engine::ecs::Registry& registry, const Camera& camera, float time,
                                    const std::vector<engine::scene::Feature*>& features,
                                    const glm::vec4& sky = {0.5f, 0.6f, 0.8f, 1.0f}) {
        using namespace engine::render;
        const glm::mat4 view = camera.view(), proj = camera.projection(float(width) / float(height));
        const glm::mat4 viewProj = proj * view;
        const engine::scene::DrawLists lists = engine::scene::extractDrawLists(registry, library, viewProj, camera.eye);
        std::vector<BufferHandle> buffers;
        auto instances = [&](const engine::scene::DrawBatch& b) {
            const auto bytes = std::as_bytes(std::span(b.instances));
            buffers.push_back(backend.createBuffer({"instances", BufferKind::Instance, bytes.size()}, bytes));
            return buffers.back();
        };
        backend.beginPass(opaque.passDesc(sky));
        for (const engine::scene::DrawBatch& b : lists.opaque) {
            const engine::scene::MeshPart& part = library.part(b.part);
            SurfaceParams s;
            s.viewProj = viewProj;
            s.baseColorFactor = part.material.baseColorFactor;
            s.baseColor = part.material.baseColor;
            s.light = kSun;
            DrawDesc d;
            d.pipeline = opaquePipeline;
            d.params = s;
            d.vertices = engine::scene::vertexBufferOf(b, part);
            d.indices = part.indices;
            d.count = part.indexCount;
            d.instances = instances(b);
            d.instanceCount = std::uint32_t(b.instances.size());
            backend.draw(d);
        }
        backend.endPass();
        std::vector<engine::render::MaskedBatch> foliage;
        for (const engine::scene::DrawBatch& b : lists.mask) {
            const engine::scene::MeshPart& part = library.part(b.part);
            engine::render::MaskedBatch f;
            f.vertices = engine::scene::vertexBufferOf(b, part);
            f.indices = part.indices;
            f.count = part.indexCount;
            f.instances = instances(b);
            f.instanceCount = std::uint32_t(b.instances.size());
            f.baseColor = part.material.baseColor;
            f.baseColorFactor = part.material.baseColorFactor;
            f.worldBounds = {b.worldBounds.min, b.worldBounds.max};
            foliage.push_back(f);
        }
        const ssam::FoliageView foliageView{viewProj, kSun, foliage};
        const engine::scene::FeatureFrame frame{
            backend, library, lists,    opaque.color(), opaque.depth(), width, height,
            view,    proj,    viewProj, camera.eye,     kSun,           time,  CompareFunc::Greater};
        test_support::OneFrameGraph one(backend);
        const ColorDepth afterSsam =
            ssam::addSsamPasses(one.graph(), *ssam, foliageView, one.import(opaque.color(), opaque.depth())).frame;
        const ColorDepth result = test_support::addFeatures(one, features, frame, afterSsam);
        if (readBackAfterFeatures) one.readBack(readBackAfterFeatures());
        one.run(result);
        readBacks = one.readBacks();
        for (BufferHandle b : buffers) backend.destroy(b);
        return backend.readback(opaque.color());
    }
};

// A camera-facing rectangle at distance z (world units along +z), for occlusion tests.
inline engine::scene::ModelId addRectangle(engine::scene::MeshLibrary& library, const char* name, float x0, float y0,
                                           float x1, float y1, float z, engine::scene::SurfaceClass surface,
                                           const glm::vec4& color) {
    using engine::render::Vertex;
    std::vector<Vertex> v(4);
    const glm::vec3 p[4] = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
    for (int i = 0; i < 4; ++i) {
        v[i].position = p[i];
        v[i].normal = {0.0f, 0.0f, -1.0f};
        v[i].uv = {float(i == 1 || i == 2), float(i >= 2)};
    }
    engine::scene::PartMaterial m;
    m.surface = surface;
    m.doubleSided = true;
    m.baseColorFactor = color;
    return library.add(name, v, {0, 1, 2, 0, 2, 3}, m);
}

inline engine::ecs::Entity place(engine::ecs::Registry& registry, engine::scene::ModelId model,
                                 const glm::vec3& at = glm::vec3(0.0f)) {
    const engine::ecs::Entity e = registry.create();
    registry.add<engine::scene::Transform>(e, engine::scene::Transform{at});
    registry.add<engine::scene::Renderable>(e, engine::scene::Renderable{model});
    return e;
}

// A scene of cards on its own soft backend (one thread) and one frame of it, seen by
// `camera`: where each module's scene tests start.
struct LivingScene {
    std::unique_ptr<engine::render::Device> backend = engine::render::soft::createSoftBackend({1, 64, false});
    engine::scene::MeshLibrary library{*backend};
    engine::ecs::Registry registry;
    LivingFrame frame;
    Camera camera;

    LivingScene(int width, int height, const Camera& view = {})
        : frame(*backend, library, width, height), camera(view) {}

    // A camera-facing card (addRectangle), placed at the origin.
    engine::ecs::Entity addCard(const char* name, float x0, float y0, float x1, float y1, float z,
                                engine::scene::SurfaceClass surface, const glm::vec4& color) {
        return place(registry, addRectangle(library, name, x0, y0, x1, y1, z, surface, color));
    }
    // The frame with `feature`'s passes (none for nullptr) at `time`.
    engine::render::Readback render(engine::scene::Feature* feature, float time = 0.0f) {
        std::vector<engine::scene::Feature*> features;
        if (feature) features.push_back(feature);
        return frame.render(registry, camera, time, features);
    }
};

}  // namespace living::testing
