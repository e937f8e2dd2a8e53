// SPDX-License-Identifier: MIT
// modules/wind: sway, collision, which plants deform, bad input, determinism, extraction of
// the deformed copies (engine/scene VertexOverride).
#include <gtest/gtest.h>

#include <cstring>

#include <glm/gtc/matrix_transform.hpp>
#include <tbb/task_arena.h>

#include "engine/core/ecs/scheduler.hpp"
#include "engine/core/error.hpp"
#include "engine/render/projection.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/components.hpp"
#include "engine/scene/draw_lists.hpp"
#include "wind/wind_feature.hpp"
#include "wind/wind_system.hpp"
#include "wind_plants.hpp"

namespace {

using namespace engine;
using engine::scene::Transform;

glm::mat4 viewProjFrom(const glm::vec3& eye, const glm::vec3& target) {
    return render::perspectiveReverseZ(1.0f, 1.5f, 0.1f, 30000.0f) * glm::lookAt(eye, target, glm::vec3(0, 1, 0));
}

struct WindScene : wind::testing::CardPlantWorld {
    glm::vec3 eye{0.0f, 2.0f, -10.0f};
    bool motionVectors = true;  // a temporal technique with motion vectors runs (WindFrame::motionVectors)

    WindScene() { registry.add<wind::Wind>(registry.create()); }

    ecs::Entity addPlant(const glm::vec3& at, float yaw = 0.0f, float scale = 1.0f) {
        const ecs::Entity e = registry.create();
        registry.add<Transform>(e, Transform{at, glm::angleAxis(yaw, glm::vec3(0, 1, 0)), glm::vec3(scale)});
        registry.add<scene::Renderable>(e, scene::Renderable{plant});
        return e;
    }
    void step(float time, float dt) {
        system.setFrame({time, dt, eye, viewProjFrom(eye, eye + glm::vec3(0, 0, 1)), true, motionVectors});
        system.update(registry);
    }
    glm::vec3 world(ecs::Entity e, const render::Vertex& v) {
        return glm::vec3(registry.get<Transform>(e).matrix() * glm::vec4(v.position, 1.0f));
    }
};

TEST(Wind, AttachGivesEveryFoliageEntityASway) {
    WindScene s;
    const ecs::Entity a = s.addPlant({0, 0, 0}), b = s.addPlant({3, 0, 0});
    const ecs::Entity rock = s.registry.create();
    std::vector<render::Vertex> v(3);
    scene::PartMaterial opaque;
    s.registry.add<scene::Renderable>(rock, scene::Renderable{s.library.add("rock", v, {0, 1, 2}, opaque)});
    EXPECT_EQ(s.system.attach(s.registry), 2u);
    EXPECT_TRUE(s.registry.has<wind::Sway>(a));
    EXPECT_TRUE(s.registry.has<wind::Sway>(b));
    EXPECT_FALSE(s.registry.has<wind::Sway>(rock));
    EXPECT_NE(s.registry.get<wind::Sway>(a).phase, s.registry.get<wind::Sway>(b).phase);
}

TEST(Wind, SwayIsZeroAtTheFootAndGrowsWithHeight) {
    WindScene s;
    const ecs::Entity e = s.addPlant({0, 0, 0});
    s.system.attach(s.registry);
    s.step(1.0f, 1.0f / 30.0f);
    const auto rest = s.library.vertices(s.library.partsOf(s.plant)[0]);
    const auto moved = s.system.deformed(e, 0);
    ASSERT_EQ(moved.size(), rest.size());
    float foot = 0.0f, top = 0.0f;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        const float d = glm::length(moved[i].position - rest[i].position);
        if (rest[i].position.y == 0.0f) foot = std::max(foot, d);
        if (rest[i].position.y == 4.0f) top = std::max(top, d);
    }
    EXPECT_LT(foot, 1e-5f);
    EXPECT_GT(top, 0.1f);  // strength 0.35 m, flexibility >= 0.6
}

TEST(Wind, ColliderLeavesNoVertexInsideAndFoliageSpringsBack) {
    WindScene s;
    const ecs::Entity e = s.addPlant({0, 0, 0});
    s.system.attach(s.registry);
    const ecs::Entity car = s.registry.create();
    s.registry.add<Transform>(car, Transform{{-3.0f, 2.0f, 0.0f}});
    s.registry.add<scene::Collider>(car, scene::Collider{1.2f});
    const auto rest = s.library.vertices(s.library.partsOf(s.plant)[0]);
    // The car drives through the middle of the crown.
    float time = 0.0f;
    std::size_t pushedAtSomePoint = 0;
    for (int frame = 0; frame < 60; ++frame, time += 1.0f / 30.0f) {
        s.registry.get<Transform>(car).position.x = -3.0f + 0.1f * float(frame);
        s.step(time, 1.0f / 30.0f);
        const glm::vec3 c = s.registry.get<Transform>(car).position;
        std::size_t inside = 0;
        for (const render::Vertex& v : s.system.deformed(e, 0)) {
            const float d = glm::length(s.world(e, v) - c);
            inside += d < 1.2f;
            pushedAtSomePoint += d < 1.2f + 0.06f;
        }
        EXPECT_EQ(inside, 0u) << "frame " << frame;
    }
    EXPECT_GT(pushedAtSomePoint, 0u);  // the collider really touched the plant
    // Without the car the push relaxes: after 3 s at springRate 3/s it is below 1e-3 of itself.
    s.registry.destroy(car);
    s.system.setFrame({time, 3.0f, s.eye, viewProjFrom(s.eye, s.eye + glm::vec3(0, 0, 1)), true});
    s.system.update(s.registry);
    WindScene calm;  // the same plant, never pushed
    const ecs::Entity twin = calm.addPlant({0, 0, 0});
    calm.registry.add<wind::Sway>(twin, s.registry.get<wind::Sway>(e));
    calm.system.setFrame({time, 3.0f, calm.eye, viewProjFrom(calm.eye, calm.eye + glm::vec3(0, 0, 1)), true});
    calm.system.update(calm.registry);
    const auto a = s.system.deformed(e, 0), b = calm.system.deformed(twin, 0);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(glm::length(a[i].position - b[i].position), 0.0f, 5e-3f);
    (void)rest;
}

TEST(Wind, OnlyPlantsInViewAndNearTheCameraOrACollierDeform) {
    WindScene s;
    const ecs::Entity near = s.addPlant({0, 0, 0});
    const ecs::Entity far = s.addPlant({0, 0, 200});
    const ecs::Entity behind = s.addPlant({0, 0, -20});
    const ecs::Entity byCar = s.addPlant({30, 0, 150});
    s.system.attach(s.registry);
    const ecs::Entity car = s.registry.create();
    s.registry.add<Transform>(car, Transform{{30.0f, 1.0f, 148.0f}});
    s.registry.add<scene::Collider>(car, scene::Collider{2.5f});
    s.step(0.5f, 1.0f / 30.0f);
    const std::size_t perPlant = s.library.vertices(s.library.partsOf(s.plant)[0]).size();
    EXPECT_EQ(s.system.stats().plantsDeformed, 2u);
    EXPECT_EQ(s.system.stats().verticesDeformed, 2 * perPlant);
    EXPECT_TRUE(s.registry.has<scene::VertexOverride>(near));
    EXPECT_TRUE(s.registry.has<scene::VertexOverride>(byCar));
    EXPECT_FALSE(s.registry.has<scene::VertexOverride>(far));
    EXPECT_FALSE(s.registry.has<scene::VertexOverride>(behind));

    // Extraction draws the near plant from its own buffer and the far one from the shared mesh.
    const scene::DrawLists lists =
        scene::extractDrawLists(s.registry, s.library, viewProjFrom(s.eye, s.eye + glm::vec3(0, 0, 1)), s.eye);
    std::size_t shared = 0, own = 0;
    for (const scene::DrawBatch& b : lists.mask) {
        if (b.vertices) {
            ++own;
            EXPECT_EQ(b.instances.size(), 1u);
        } else {
            shared += b.instances.size();
        }
        EXPECT_EQ(scene::vertexBufferOf(b, s.library.part(b.part)),
                  b.vertices ? b.vertices : s.library.part(b.part).vertices);
    }
    EXPECT_EQ(own, 2u);
    EXPECT_EQ(shared, 1u);  // `far` (in view, not near); `behind` is culled

    // The camera leaves: the near plant goes back to the shared mesh and gives its buffer back.
    const std::size_t released = s.system.stats().buffersReleased;
    s.eye = {0.0f, 2.0f, -500.0f};
    s.registry.destroy(car);
    s.step(0.6f, 1.0f / 30.0f);
    EXPECT_EQ(s.system.stats().plantsDeformed, 0u);
    EXPECT_FALSE(s.registry.has<scene::VertexOverride>(near));
    EXPECT_EQ(s.system.stats().buffersReleased, released + 2);
}

TEST(Wind, BadParametersAreRefusedWithTheirName) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    auto message = [](const wind::Wind& w) {
        try {
            wind::validate(w);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    wind::Wind w;
    EXPECT_EQ(message(w), "accepted");
    w.strength = nan;
    EXPECT_NE(message(w).find("Wind.strength is not finite"), std::string::npos);
    w = {};
    w.gustFrequency = inf;
    EXPECT_NE(message(w).find("Wind.gustFrequency"), std::string::npos);
    w = {};
    w.activeRadius = -1.0f;
    EXPECT_NE(message(w).find("Wind.activeRadius = -1"), std::string::npos);
    w = {};
    w.direction = {0.0f, 1.0f, 0.0f};
    EXPECT_NE(message(w).find("no horizontal component"), std::string::npos);
    w = {};
    w.direction.x = nan;
    EXPECT_NE(message(w).find("Wind.direction"), std::string::npos);
    w = {};
    w.gustWavelength = 0.0f;
    EXPECT_NE(message(w).find("gustWavelength"), std::string::npos);

    // Through the scheduler the error names the system and its phase too.
    WindScene s;
    s.addPlant({0, 0, 0});
    wind::WindFeature feature(s.registry, s.library);
    s.registry.view<wind::Wind>().each([&](wind::Wind& wind) { wind.springRate = nan; });
    ecs::Scheduler scheduler;
    feature.registerSystems(scheduler);
    try {
        scheduler.run(s.registry);
        FAIL() << "a NaN springRate was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("wind"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("springRate"), std::string::npos);
    }
    // A second Wind is refused; a bad dt too.
    s.registry.view<wind::Wind>().each([&](wind::Wind& wind) { wind = {}; });
    s.registry.add<wind::Wind>(s.registry.create());
    EXPECT_THROW(s.system.update(s.registry), Error);
}

TEST(Wind, NegativeOrNanDtAndWeirdSwayAreHandled) {
    WindScene s;
    const ecs::Entity e = s.addPlant({0, 0, 0});
    s.registry.add<wind::Sway>(e, wind::Sway{std::numeric_limits<float>::quiet_NaN(), 1e30f});
    s.system.setFrame({0.0f, -1.0f, s.eye, glm::mat4(1.0f), false});
    EXPECT_THROW(s.system.update(s.registry), Error);
    s.system.setFrame({0.0f, std::numeric_limits<float>::quiet_NaN(), s.eye, glm::mat4(1.0f), false});
    EXPECT_THROW(s.system.update(s.registry), Error);
    s.system.setFrame({1.0f, 0.1f, s.eye, glm::mat4(1.0f), false});
    s.system.update(s.registry);  // NaN flexibility is taken as rigid
    for (const render::Vertex& v : s.system.deformed(e, 0))
        for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(v.position[c]));
}

TEST(Wind, NoWindEntityMeansRestMeshes) {
    WindScene s;
    const ecs::Entity e = s.addPlant({0, 0, 0});
    s.system.attach(s.registry);
    s.step(0.0f, 0.1f);
    EXPECT_TRUE(s.registry.has<scene::VertexOverride>(e));
    std::vector<ecs::Entity> winds;
    s.registry.view<const wind::Wind>().each([&](ecs::Entity w, const wind::Wind&) { winds.push_back(w); });
    for (ecs::Entity w : winds) s.registry.destroy(w);
    s.step(0.1f, 0.1f);
    EXPECT_FALSE(s.registry.has<scene::VertexOverride>(e));
}

// The motion copy: this frame's deformed vertices with each normal the previous frame's
// position minus this one's (the rest mesh's on the first frame, when the plant was drawn at
// rest), and extraction hands it to the plant's own batch beside its deformed copy.
TEST(Wind, TheMotionCopyHoldsEachVertexsMotionSinceThePreviousFrame) {
    WindScene s;
    const ecs::Entity e = s.addPlant({0, 0, 0});
    s.system.attach(s.registry);
    s.step(0.5f, 0.1f);
    const std::vector<render::Vertex> first(s.system.deformed(e, 0).begin(), s.system.deformed(e, 0).end());
    ASSERT_FALSE(first.empty());
    const auto rest = s.library.vertices(s.library.partsOf(s.plant)[0]);
    for (std::size_t i = 0; i < first.size(); ++i)
        EXPECT_EQ(s.system.motion(e, 0)[i].normal, rest[i].position - first[i].position) << i;
    s.step(0.6f, 0.1f);
    const auto now = s.system.deformed(e, 0), motion = s.system.motion(e, 0);
    ASSERT_EQ(motion.size(), now.size());
    float moved = 0.0f;
    for (std::size_t i = 0; i < now.size(); ++i) {
        EXPECT_EQ(motion[i].position, now[i].position) << i;
        EXPECT_EQ(motion[i].uv, now[i].uv) << i;
        EXPECT_EQ(motion[i].normal, first[i].position - now[i].position) << i;
        moved = std::max(moved, glm::length(motion[i].normal));
    }
    EXPECT_GT(moved, 1e-3f) << "the wind moved the card between the frames";
    const auto& override = s.registry.get<scene::VertexOverride>(e);
    ASSERT_EQ(override.motionBuffers.size(), override.buffers.size());
    EXPECT_TRUE(override.motionBuffers[0]);
    const scene::DrawLists lists =
        scene::extractDrawLists(s.registry, s.library, viewProjFrom(s.eye, s.eye + glm::vec3(0, 0, 1)), s.eye);
    bool found = false;
    for (const scene::DrawBatch& b : lists.mask)
        if (b.vertices == override.buffers[0]) found = b.motionVertices == override.motionBuffers[0];
    EXPECT_TRUE(found) << "the plant's own batch carries its motion copy";
}

// No technique reads motion vectors (none with history runs): the wind bends the plant the
// same, but computes, uploads and makes a buffer for no motion copy; asked again, the copy is
// back, with the motion since the frame drawn before.
TEST(Wind, NoMotionCopyWithoutATechniqueThatReadsMotion) {
    WindScene with, without;
    without.motionVectors = false;
    const ecs::Entity e = with.addPlant({0, 0, 0}), f = without.addPlant({0, 0, 0});
    with.system.attach(with.registry);
    without.system.attach(without.registry);
    for (int i = 0; i < 3; ++i) {
        with.step(0.5f + 0.1f * float(i), 0.1f);
        without.step(0.5f + 0.1f * float(i), 0.1f);
        EXPECT_GT(with.system.stats().motionCopies, 0u);
        EXPECT_EQ(without.system.stats().motionCopies, 0u);
    }
    const auto bent = with.system.deformed(e, 0), bentToo = without.system.deformed(f, 0);
    ASSERT_EQ(bent.size(), bentToo.size());
    EXPECT_EQ(std::memcmp(bent.data(), bentToo.data(), bent.size() * sizeof(render::Vertex)), 0);
    EXPECT_TRUE(without.system.motion(f, 0).empty());
    const auto& override = without.registry.get<scene::VertexOverride>(f);
    for (render::BufferHandle b : override.motionBuffers) EXPECT_FALSE(b);
    const scene::DrawLists lists = scene::extractDrawLists(
        without.registry, without.library, viewProjFrom(without.eye, without.eye + glm::vec3(0, 0, 1)), without.eye);
    for (const scene::DrawBatch& b : lists.mask) EXPECT_FALSE(b.motionVertices);

    const std::vector<render::Vertex> drawn(bentToo.begin(), bentToo.end());
    without.motionVectors = true;
    without.step(0.8f, 0.1f);
    const auto now = without.system.deformed(f, 0), motion = without.system.motion(f, 0);
    ASSERT_EQ(motion.size(), now.size());
    for (std::size_t i = 0; i < now.size(); ++i) EXPECT_EQ(motion[i].normal, drawn[i].position - now[i].position) << i;
    EXPECT_TRUE(without.registry.get<scene::VertexOverride>(f).motionBuffers.at(0));
}

// The same frames give the same bits, for 1 and 2 threads.
std::vector<render::Vertex> simulate(int threads) {
    WindScene s;
    std::vector<ecs::Entity> plants;
    for (int i = 0; i < 12; ++i)
        plants.push_back(s.addPlant({float(i % 4) * 2.5f - 4.0f, 0.0f, float(i / 4) * 2.5f}, 0.3f * i, 0.9f));
    s.system.attach(s.registry, 7);
    const ecs::Entity car = s.registry.create();
    s.registry.add<Transform>(car);
    s.registry.add<scene::Collider>(car, scene::Collider{1.5f});
    tbb::task_arena arena(threads);
    arena.execute([&] {
        for (int f = 0; f < 20; ++f) {
            s.registry.get<Transform>(car).position = {-5.0f + 0.5f * f, 1.0f, 2.5f};
            s.step(float(f) / 30.0f, 1.0f / 30.0f);
        }
    });
    std::vector<render::Vertex> all;
    for (ecs::Entity e : plants) {
        const auto v = s.system.deformed(e, 0);
        all.insert(all.end(), v.begin(), v.end());
    }
    return all;
}

TEST(Wind, DeterministicForAnyThreadCount) {
    const std::vector<render::Vertex> one = simulate(1), again = simulate(1), two = simulate(2);
    ASSERT_FALSE(one.empty());
    ASSERT_EQ(one.size(), two.size());
    EXPECT_EQ(std::memcmp(one.data(), again.data(), one.size() * sizeof(render::Vertex)), 0);
    EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(render::Vertex)), 0);
}

}  // namespace
