// SPDX-License-Identifier: MIT
// The player's car bends the bushes it drives through: it keeps the
// autopilot's Collider, so modules/wind pushes foliage out of its sphere. Two identical racing
// scenes, seen from the same camera at the same times: in one the player drives the car
// through a bush, in the other away from it; the bush's deformed vertices (its own buffer's
// bounds) differ only where the car went through.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

#include "content_dir.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/components.hpp"
#include "living_scene.hpp"
#include "racing_scene.hpp"

namespace racer {
namespace {

using engine::scene::Transform;

// The bush (a plant lower than 3 m) nearest the car's start, off the road.
engine::ecs::Entity bushNearTheStart(RacingScene& scene) {
    const glm::vec3 start = scene.registry().get<Car>(scene.car()).position;
    engine::ecs::Entity best{};
    float bestDistance = std::numeric_limits<float>::infinity();
    scene.registry().view<const Transform, const engine::scene::Renderable>().each(
        [&](engine::ecs::Entity e, const Transform& t, const engine::scene::Renderable& r) {
            if (e == scene.car()) return;
            const engine::scene::Aabb b = scene.library().bounds(r.model);
            const float height = (b.max.y - b.min.y) * t.scale.y, width = (b.max.x - b.min.x) * t.scale.x;
            if (height > 3.0f || height < 0.3f || width > 8.0f) return;  // not terrain, road or a tree
            const float d = glm::length(t.position - start);
            if (d > 8.0f && d < bestDistance) bestDistance = d, best = e;
        });
    return best;
}

struct DrivenScene {
    explicit DrivenScene(engine::render::Backend& backend)
        : scene(backend, SceneOptions{defaultContentDir(), 1}),
          living(scene.registry(), scene.library(),
                 LivingSceneOptions{
                     .enabled = onlyModules(featureModules(), {"wind"}), .seed = 1, .track = &scene.track()}) {}

    // The player's car 10 m before `target` (coming from the start), driving at it or away from it.
    void aim(const glm::vec3& target, bool towards) {
        scene.takeWheel({});
        Car& car = scene.registry().get<Car>(scene.car());
        const glm::vec3 along = glm::normalize(glm::vec3(target.x - car.position.x, 0.0f, target.z - car.position.z));
        const glm::vec3 from = target - along * 10.0f;
        const glm::vec3 heading = towards ? along : -along;
        car.motion = CarMotion{from, std::atan2(heading.x, heading.z), 12.0f, 0.0f};
    }

    RacingScene scene;
    LivingScene living;
};

TEST(DriveCollision, TheDrivenCarBendsTheBushItDrivesThrough) {
    auto soft = engine::render::soft::createSoftBackend({2, 64, false});
    DrivenScene through(*soft), away(*soft);
    const engine::ecs::Entity bush = bushNearTheStart(through.scene);
    ASSERT_TRUE(through.scene.registry().alive(bush)) << "no bush in the scene";
    const glm::vec3 at = through.scene.registry().get<Transform>(bush).position;
    through.aim(at, true);
    away.aim(at, false);
    // The same camera for both, close enough that the bush sways (deforms) in both.
    CameraView view;
    view.eye = at + glm::vec3(0.0f, 4.0f, -14.0f);
    view.view = glm::lookAt(view.eye, at, glm::vec3(0.0f, 1.0f, 0.0f));
    view.projection = glm::perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 1000.0f);
    view.viewProj = view.projection * view.view;
    constexpr float dt = 1.0f / 30.0f;
    int framesDiffering = 0, framesBothDeformed = 0;
    float closest = std::numeric_limits<float>::infinity();
    for (int i = 0; i < 40; ++i) {
        for (DrivenScene* s : {&through, &away}) {
            s->scene.update(dt);
            s->living.update(float(i) * dt, dt, view);
        }
        const Car& car = through.scene.registry().get<Car>(through.scene.car());
        ASSERT_TRUE(car.driven);
        closest = std::min(closest, glm::length(glm::vec2(car.position.x - at.x, car.position.z - at.z)));
        auto* a = through.scene.registry().tryGet<engine::scene::VertexOverride>(bush);
        auto* b = away.scene.registry().tryGet<engine::scene::VertexOverride>(bush);
        if (!a || !b) continue;
        ++framesBothDeformed;
        bool differ = false;
        for (std::size_t k = 0; k < std::min(a->bounds.size(), b->bounds.size()); ++k)
            differ = differ || a->bounds[k].min != b->bounds[k].min || a->bounds[k].max != b->bounds[k].max;
        framesDiffering += differ;
    }
    EXPECT_LT(closest, 1.0f) << "the car did not reach the bush";
    EXPECT_GT(framesBothDeformed, 30) << "the bush did not sway in both scenes (the camera is not near it)";
    EXPECT_GT(framesDiffering, 0) << "driving through the bush did not bend it";
    EXPECT_LT(framesDiffering, framesBothDeformed) << "the scenes differ before the car arrives: not the collision";
}

}  // namespace
}  // namespace racer
