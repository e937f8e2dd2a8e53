// SPDX-License-Identifier: MIT
// The racing scene's forest (game/src/forest.hpp): woodland lines the road for most
// of the lap, a tree line a few metres off the asphalt, canopy reaching over it in places, bushes
// on the verges, clearings without trees near the road; nothing grows on the road or its
// shoulders; the same seed grows the same forest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "content_dir.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/components.hpp"
#include "racing_scene.hpp"

namespace {

using namespace racer;
using engine::scene::Renderable;
using engine::scene::SurfaceClass;
using engine::scene::Transform;

struct Plant {
    Track::Nearest at;   // along the lap and off the centre line
    float reach = 0.0f;  // the horizontal half-extent of its foliage, metres
    bool tree = false;   // a trunk (an opaque part) under the leaves
    glm::vec3 position{0.0f};
};

struct Forest {
    // mutable: RacingScene's registry is for systems to change; this file only reads it.
    std::unique_ptr<engine::render::Device> backend = engine::render::soft::createSoftBackend({1, 64, false});
    mutable RacingScene scene{*backend, SceneOptions{defaultContentDir(), 1}};
    std::vector<Plant> plants;

    Forest() {
        const engine::scene::MeshLibrary& library = scene.library();
        scene.registry().view<const Transform, const Renderable>().each([&](const Transform& t, const Renderable& r) {
            Plant plant;
            bool foliage = false;
            for (std::uint32_t part : library.partsOf(r.model)) {
                const engine::scene::MeshPart& p = library.part(part);
                if (p.material.surface == SurfaceClass::Mask) {
                    foliage = true;
                    plant.reach =
                        std::max({plant.reach, p.bounds.max.x, -p.bounds.min.x, p.bounds.max.z, -p.bounds.min.z});
                } else if (p.material.surface == SurfaceClass::Opaque) {
                    plant.tree = true;
                }
            }
            if (!foliage) return;
            plant.reach *= t.scale.x;
            plant.position = t.position;
            plant.at = scene.track().nearest(t.position);
            plants.push_back(plant);
        });
    }
};

const Forest& forest() {
    static const Forest f;  // one scene for every test of this file
    return f;
}

TEST(Forest, NothingGrowsOnTheRoadOrItsShoulders) {
    const float edge = 0.5f * forest().scene.track().width() + Track::kShoulderWidth;
    ASSERT_GT(forest().plants.size(), 2000u);
    for (const Plant& p : forest().plants)
        EXPECT_GE(p.at.offset, edge) << "a plant at (" << p.position.x << ", " << p.position.z << ")";
}

// Through the woodland (the lap outside its clearings), every 20 m of road has a tree within a
// few metres of the asphalt on each side.
TEST(Forest, TreeLinesStandAFewMetresFromTheRoad) {
    const Track& track = forest().scene.track();
    const float halfWidth = 0.5f * track.width();
    int stretches = 0;
    for (float d = 0.0f; d + 20.0f <= track.length(); d += 20.0f) {
        if (!inWoodland(track, d) || !inWoodland(track, d + 20.0f)) continue;
        ++stretches;
        for (int side = -1; side <= 1; side += 2) {
            const bool lined = std::any_of(forest().plants.begin(), forest().plants.end(), [&](const Plant& p) {
                if (!p.tree || p.at.distance < d || p.at.distance >= d + 20.0f || p.at.offset > halfWidth + 5.0f)
                    return false;
                const glm::vec3 side0 = glm::cross(track.forward(p.at.distance), glm::vec3(0.0f, 1.0f, 0.0f));
                return glm::dot(p.position - track.position(p.at.distance), side0) * float(side) > 0.0f;
            });
            EXPECT_TRUE(lined) << "no tree within 5 m of the asphalt on side " << side << " of " << d << " .. "
                               << d + 20.0f << " m";
        }
    }
    EXPECT_GT(stretches, int(0.6f * track.length() / 20.0f)) << "woodland along most of the lap";
}

// Big trees whose crowns reach over the asphalt, and bushes on the verges.
TEST(Forest, CanopyOverhangsTheRoadAndBushesLineTheVerges) {
    const float halfWidth = 0.5f * forest().scene.track().width();
    int overhanging = 0, verge = 0;
    for (const Plant& p : forest().plants) {
        overhanging += p.tree && p.at.offset - p.reach < halfWidth - 1.0f;
        verge += !p.tree && p.at.offset < halfWidth + Track::kShoulderWidth + 3.0f;
    }
    EXPECT_GE(overhanging, 100) << "trees whose crown reaches a metre or more over the asphalt";
    EXPECT_GE(verge, 500) << "bushes on the verges";
}

// In each clearing no tree stands within 25 m of the road: the view opens onto the hills.
// (The tree line's last trunk before a clearing may stand a metre inside it: its edges are
// left out.)
TEST(Forest, ClearingsHaveNoTreesNearTheRoad) {
    const Track& track = forest().scene.track();
    int clearingMetres = 0;
    for (float d = 0.0f; d < track.length(); d += 1.0f) {
        if (inWoodland(track, d - 3.0f) || inWoodland(track, d) || inWoodland(track, d + 3.0f)) continue;
        ++clearingMetres;
        for (const Plant& p : forest().plants) {
            if (p.tree && std::abs(p.at.distance - d) < 0.5f) {
                EXPECT_GT(p.at.offset, 25.0f) << "a tree in the clearing at " << d << " m";
            }
        }
    }
    EXPECT_GT(clearingMetres, int(0.1f * track.length()));
}

TEST(Forest, SameSeedSameForest) {
    auto backend = engine::render::soft::createSoftBackend({1, 64, false});
    RacingScene again(*backend, SceneOptions{defaultContentDir(), 1});
    std::vector<glm::vec3> first, second;
    forest().scene.registry().view<const Transform>().each([&](const Transform& t) { first.push_back(t.position); });
    again.registry().view<const Transform>().each([&](const Transform& t) { second.push_back(t.position); });
    EXPECT_EQ(first, second);
}

}  // namespace
