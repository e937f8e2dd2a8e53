// SPDX-License-Identifier: MIT
// [Hathaway 2010] §3.3: wind and collisions make neighbouring trees "overlap rather unpredictably",
// which no offline sort can handle. SSAM needs no sorting (§3.5, §3.8): here two content
// trees are deformed by modules/wind (sway, gusts, flutter, and a collider pushing through
// both crowns) until they interpenetrate, and the SSAM frame drawn with the trees in one
// order equals, bit for bit (soft backend), the frame drawn with the order reversed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/assets/gltf.hpp"
#include "engine/render/frame_targets.hpp"
#include "engine/render/projection.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/components.hpp"
#include "engine/scene/draw_lists.hpp"
#include "ssam/ssam.hpp"
#include "wind/wind_system.hpp"
#include "run_ssam.hpp"

namespace {

using namespace engine;
using namespace engine::render;

constexpr int kWidth = 192, kHeight = 144;
const DirectionalLight kSun{{0.45f, 0.80f, 0.35f}, {1.05f, 0.98f, 0.88f}, {0.32f, 0.36f, 0.42f}};

struct Frame {
    Readback color, depth;
};

struct TwoTrees {
    std::unique_ptr<engine::render::Device> backend = soft::createSoftBackend({2, 64, false});
    scene::MeshLibrary library{*backend};
    ecs::Registry registry;
    wind::WindSystem wind{library};
    glm::vec3 eye{0.0f, 3.5f, -8.0f};
    glm::mat4 viewProj = perspectiveReverseZ(0.9f, float(kWidth) / kHeight, 0.1f, 30000.0f) *
                         glm::lookAt(eye, glm::vec3(0.0f, 3.5f, 0.0f), glm::vec3(0, 1, 0));
    ecs::Entity trees[2];

    TwoTrees() {
        const scene::ModelId tree =
            library.add(assets::loadGltf(std::filesystem::path(SSAM_SOURCE_DIR) / "content/models/tree_broadleaf.glb"));
        const glm::vec3 at[2] = {{-0.9f, 0.0f, 0.0f}, {0.9f, 0.0f, 0.6f}};
        for (int i = 0; i < 2; ++i) {
            trees[i] = registry.create();
            registry.add<scene::Transform>(trees[i],
                                           scene::Transform{at[i], glm::angleAxis(1.3f * i, glm::vec3(0, 1, 0))});
            registry.add<scene::Renderable>(trees[i], scene::Renderable{tree});
        }
        wind::Wind w;
        w.strength = 1.2f;  // a storm: crowns lean into each other
        w.direction = {1.0f, 0.0f, 0.2f};
        w.flutterAmplitude = 0.1f;
        registry.add<wind::Wind>(registry.create(), w);
        wind.attach(registry, 3);
    }

    void deform(int frames, bool withCollider) {
        ecs::Entity car;
        if (withCollider) {
            car = registry.create();
            registry.add<scene::Transform>(car);
            registry.add<scene::Collider>(car, scene::Collider{1.0f});
        }
        for (int f = 0; f < frames; ++f) {
            if (withCollider) registry.get<scene::Transform>(car).position = {-1.5f + 0.2f * f, 3.0f, 0.3f};
            wind.setFrame({1.0f + f / 30.0f, 1.0f / 30.0f, eye, viewProj, true});
            wind.update(registry);
        }
    }

    // Plain unsorted alpha blending of the same batches instead of SSAM: the control that
    // shows the scene really is order-sensitive.
    Frame render(bool reversed, bool unsortedBlend = false) {
        engine::render::FrameTargets opaque(*backend, {kWidth, kHeight, 1, Format::RGBA8_SRGB, CompareFunc::Greater});
        ssam::Settings config;
        config.depthTest = ssam::DepthTest::Greater;
        ssam::ScreenSpaceAlphaMask ssam(*backend, config);
        const scene::DrawLists lists = scene::extractDrawLists(registry, library, viewProj, eye);
        std::vector<BufferHandle> buffers;
        std::vector<engine::render::MaskedBatch> batches;
        for (const scene::DrawBatch& b : lists.mask) {
            const scene::MeshPart& part = library.part(b.part);
            const auto bytes = std::as_bytes(std::span(b.instances));
            buffers.push_back(backend->createBuffer({"instances", BufferKind::Instance, bytes.size()}, bytes));
            engine::render::MaskedBatch f;
            f.vertices = scene::vertexBufferOf(b, part);
            f.indices = part.indices;
            f.count = part.indexCount;
            f.instances = buffers.back();
            f.instanceCount = std::uint32_t(b.instances.size());
            f.baseColor = part.material.baseColor;
            f.baseColorFactor = part.material.baseColorFactor;
            f.worldBounds = {b.worldBounds.min, b.worldBounds.max};
            batches.push_back(f);
        }
        // Deformed: each tree's leaves from its own copy; at rest: one instanced batch.
        EXPECT_EQ(batches.size(), registry.has<scene::VertexOverride>(trees[0]) ? 2u : 1u);
        if (reversed) std::reverse(batches.begin(), batches.end());
        backend->beginPass(opaque.passDesc({0.55f, 0.70f, 0.88f, 1.0f}));
        backend->endPass();
        if (unsortedBlend) {
            PipelineDesc p;
            p.name = "unsorted blend";
            p.program = ProgramKind::MaskedLit;
            p.blend[0] = BlendState::alphaOver();
            p.depth = DepthState::testOnly(CompareFunc::Greater);
            const PipelineHandle pipeline = backend->createPipeline(p);
            PassDesc pass;
            pass.name = "unsorted";
            pass.color[0] = {opaque.color(), LoadOp::Load};
            pass.depth = {opaque.depth(), LoadOp::Load};
            backend->beginPass(pass);
            for (const engine::render::MaskedBatch& f : batches) {
                DrawDesc d;
                d.pipeline = pipeline;
                d.params = SurfaceParams{viewProj, f.baseColorFactor, f.baseColor, kSun};
                d.vertices = f.vertices;
                d.indices = f.indices;
                d.count = f.count;
                d.instances = f.instances;
                d.instanceCount = f.instanceCount;
                backend->draw(d);
            }
            backend->endPass();
            backend->destroy(pipeline);
        } else {
            test_support::runSsam(ssam, {opaque.color(), opaque.depth()}, {viewProj, kSun, batches});
        }
        Frame frame{backend->readback(opaque.color()), backend->readback(opaque.depth())};
        for (BufferHandle b : buffers) backend->destroy(b);
        return frame;
    }
};

bool identical(const Readback& a, const Readback& b) {
    return a.values.size() == b.values.size() &&
           std::memcmp(a.values.data(), b.values.data(), a.values.size() * sizeof(float)) == 0;
}

TEST(WindSsam, DeformedInterpenetratingTreesNeedNoSorting) {
    TwoTrees scene;
    const Frame rest = scene.render(false);  // (no Wind update yet: the shared meshes)
    scene.deform(12, true);

    // The deformed crowns really interpenetrate: their boxes overlap by more than a metre.
    scene::Aabb box[2];
    for (int i = 0; i < 2; ++i) {
        const auto& o = scene.registry.get<scene::VertexOverride>(scene.trees[i]);
        const glm::mat4 m = scene.registry.get<scene::Transform>(scene.trees[i]).matrix();
        for (const scene::Aabb& b : o.bounds) box[i].add(b.transformed(m));
    }
    const float overlapX = std::min(box[0].max.x, box[1].max.x) - std::max(box[0].min.x, box[1].min.x);
    EXPECT_GT(overlapX, 1.0f);

    const Frame forward = scene.render(false), backward = scene.render(true);
    EXPECT_TRUE(identical(forward.color, backward.color)) << "SSAM colour depends on draw order";
    EXPECT_TRUE(identical(forward.depth, backward.depth)) << "foliage depth depends on draw order";
    EXPECT_FALSE(identical(forward.color, rest.color)) << "the wind moved nothing";
    // The control: unsorted alpha blending of the same trees does depend on the order.
    EXPECT_FALSE(identical(scene.render(false, true).color, scene.render(true, true).color));

    // And a frame later, with the trees moved again, still no order dependence.
    scene.deform(5, true);
    EXPECT_TRUE(identical(scene.render(false).color, scene.render(true).color));
}

}  // namespace
