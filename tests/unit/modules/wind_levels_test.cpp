// SPDX-License-Identifier: MIT
// modules/wind with levels of detail (engine/scene/levels_of_detail.hpp): the bend eases to
// rest before a plant may leave its full model, continuously, so nothing snaps when the level
// changes; a coarser level never moves; a plant without levels bends as before.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/render/projection.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/components.hpp"
#include "engine/scene/levels_of_detail.hpp"
#include "wind/wind_system.hpp"
#include "wind_plants.hpp"

namespace {

using namespace engine;

TEST(WindLevels, RestWeightEasesContinuouslyToZero) {
    EXPECT_EQ(wind::restWeight(0.0f, 20.0f), 1.0f);
    EXPECT_EQ(wind::restWeight(wind::kEaseStart * 20.0f, 20.0f), 1.0f);
    EXPECT_EQ(wind::restWeight(20.0f, 20.0f), 0.0f);
    EXPECT_EQ(wind::restWeight(1000.0f, 20.0f), 0.0f);
    float previous = 1.0f, steepest = 0.0f;
    for (float d = 0.0f; d <= 25.0f; d += 0.01f) {
        const float w = wind::restWeight(d, 20.0f);
        EXPECT_LE(w, previous);
        steepest = std::max(steepest, previous - w);
        previous = w;
    }
    // smoothstep's steepest slope is 1.5 / width: 0.01 m moves it by at most ~0.0019 here.
    EXPECT_LT(steepest, 1.5f * 0.01f / ((1.0f - wind::kEaseStart) * 20.0f) * 1.01f);
}

// One plant walked away from the camera, the wind's clock stopped, so only the distance
// changes the bend.
struct Walk : wind::testing::CardPlantWorld {
    ecs::Entity e = registry.create();

    explicit Walk(bool levels) {
        registry.add<wind::Wind>(registry.create());
        registry.add<scene::Transform>(e);
        registry.add<scene::Renderable>(e, scene::Renderable{plant});
        system.attach(registry);
        if (levels) {
            scene::LevelsOfDetail lod;
            lod.models = {plant, plant, plant};
            lod.levels = 3;
            lod.chosen = true;
            lod.fullDetailUntil = 20.0f;
            registry.add<scene::LevelsOfDetail>(e, lod);
        }
    }
    // The largest distance of a vertex from its rest position with the camera `distance` in
    // front of the plant; 0 when the plant is drawn from the shared (rest) mesh.
    float bendAt(float distance) {
        const glm::vec3 eye(0.0f, 2.0f, -distance);
        const glm::mat4 viewProj = render::perspectiveReverseZ(1.0f, 1.5f, 0.1f, 30000.0f) *
                                   glm::lookAt(eye, glm::vec3(0, 2, 0), glm::vec3(0, 1, 0));
        system.setFrame({3.0f, 0.0f, eye, viewProj, true});
        system.update(registry);
        const auto deformed = system.deformed(e, 0);
        if (deformed.empty()) return 0.0f;
        const auto& rest = library.vertices(library.partsOf(plant)[0]);
        float most = 0.0f;
        for (std::size_t i = 0; i < rest.size(); ++i)
            most = std::max(most, glm::length(deformed[i].position - rest[i].position));
        return most;
    }
};

TEST(WindLevels, BendEasesToRestBeforeTheFullModelIsLeft) {
    Walk walk(true);
    const float nearBend = walk.bendAt(5.0f);
    ASSERT_GT(nearBend, 0.05f) << "near, the plant bends in full";
    float previous = nearBend, largestStep = 0.0f;
    for (float d = 5.0f; d <= 30.0f; d += 0.05f) {
        const float bend = walk.bendAt(d);
        largestStep = std::max(largestStep, std::abs(bend - previous));
        previous = bend;
        if (d >= 20.0f) {
            EXPECT_EQ(bend, 0.0f) << "at rest from fullDetailUntil on, d = " << d;
        }
    }
    // No snap: 5 cm of camera travel changes the bend by a small part of it (smoothstep over 8 m).
    EXPECT_LT(largestStep, 0.02f * nearBend);
    EXPECT_EQ(walk.system.stats().plantsDeformed, 0u) << "beyond it the plant costs nothing";
    // A coarser level never moves, however near.
    walk.registry.get<scene::LevelsOfDetail>(walk.e).level = 1;
    EXPECT_EQ(walk.bendAt(5.0f), 0.0f);
}

TEST(WindLevels, PlantsWithoutLevelsBendInFullUpToTheActiveRadius) {
    Walk walk(false);
    const float nearBend = walk.bendAt(5.0f);
    EXPECT_GT(nearBend, 0.05f);
    EXPECT_EQ(walk.bendAt(30.0f), nearBend) << "as before levels of detail: no easing";
    EXPECT_EQ(walk.bendAt(60.0f), 0.0f) << "beyond Wind::activeRadius";
}

}  // namespace
