// SPDX-License-Identifier: MIT
// Levels of detail (engine/scene/levels_of_detail.hpp, game/src/plant_levels.hpp): the level
// chosen per height on screen with hysteresis, the committed plants' levels chosen by distance
// and drawn by extraction with their counts, and the counts in racer's frame graph dump.
#include <gtest/gtest.h>

#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "camera_rig.hpp"
#include "content_dir.hpp"
#include "content_files.hpp"
#include "engine/render/projection.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/scene/components.hpp"
#include "engine/scene/draw_lists.hpp"
#include "frame_renderer.hpp"
#include "hud_text.hpp"
#include "plant_levels.hpp"
#include "racing_scene.hpp"

namespace {

using namespace engine;
using scene::chooseLevel;

const float kBelow[] = {60.0f, 40.0f};

TEST(LevelsOfDetail, FirstChoiceFollowsTheThresholds) {
    EXPECT_EQ(chooseLevel(0, false, 100.0f, kBelow, 0.1f), 0);
    EXPECT_EQ(chooseLevel(0, false, 59.0f, kBelow, 0.1f), 1);
    EXPECT_EQ(chooseLevel(2, false, 45.0f, kBelow, 0.1f), 1);
    EXPECT_EQ(chooseLevel(0, false, 39.0f, kBelow, 0.1f), 2);
    EXPECT_EQ(chooseLevel(0, false, 1.0f, {}, 0.1f), 0) << "a model without levels stays full";
}

TEST(LevelsOfDetail, HysteresisKeepsALevelInsideTheBand) {
    // Within 10 % of a threshold the current level stays, whichever side it came from.
    EXPECT_EQ(chooseLevel(0, true, 55.0f, kBelow, 0.1f), 0);
    EXPECT_EQ(chooseLevel(0, true, 53.0f, kBelow, 0.1f), 1);
    EXPECT_EQ(chooseLevel(1, true, 65.0f, kBelow, 0.1f), 1);
    EXPECT_EQ(chooseLevel(1, true, 67.0f, kBelow, 0.1f), 0);
    EXPECT_EQ(chooseLevel(1, true, 37.0f, kBelow, 0.1f), 1);
    EXPECT_EQ(chooseLevel(1, true, 35.0f, kBelow, 0.1f), 2);
    EXPECT_EQ(chooseLevel(2, true, 130.0f, kBelow, 0.1f), 0) << "a large jump crosses every level";
    // An instance hovering at a threshold changes level once, not every frame.
    int level = chooseLevel(0, false, 61.0f, kBelow, 0.1f), changes = 0;
    for (int frame = 0; frame < 100; ++frame) {
        const int next = chooseLevel(level, true, 60.0f + 4.0f * float(frame % 2 ? 1 : -1), kBelow, 0.1f);
        changes += next != level;
        level = next;
    }
    EXPECT_EQ(changes, 0);
    // Without a band every crossing flips.
    level = 0;
    for (int frame = 0; frame < 100; ++frame) {
        const int next = chooseLevel(level, true, 60.0f + 4.0f * float(frame % 2 ? 1 : -1), kBelow, 0.0f);
        changes += next != level;
        level = next;
    }
    EXPECT_GE(changes, 99);
}

// Across a crossfade band both levels draw, their weights summing to one and moving
// continuously: from 100 pixels to 1 in steps of 0.05 no level's weight jumps.
TEST(LevelsOfDetail, CrossfadeWeightsSumToOneAndNeverJump) {
    std::array<float, 3> before{1.0f, 0.0f, 0.0f};
    int crossfading = 0;
    for (float pixels = 100.0f; pixels >= 1.0f; pixels -= 0.05f) {
        const scene::LodBlend blend = scene::crossfadeLevels(pixels, kBelow, 0.1f);
        std::array<float, 3> weight{};
        weight[std::size_t(blend.levels[0])] += 1.0f - blend.coarserWeight;
        weight[std::size_t(blend.levels[1])] += blend.coarserWeight;
        EXPECT_FLOAT_EQ(weight[0] + weight[1] + weight[2], 1.0f) << pixels;
        EXPECT_GE(blend.coarserWeight, 0.0f);
        EXPECT_LE(blend.coarserWeight, 1.0f);
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_LT(std::abs(weight[k] - before[k]), 0.01f) << pixels << " level " << k;
        before = weight;
        const bool inBand = std::abs(pixels - 60.0f) < 6.0f || std::abs(pixels - 40.0f) < 4.0f;
        EXPECT_EQ(blend.crossfading(), inBand) << pixels;
        if (!blend.crossfading()) {
            EXPECT_EQ(blend.levels[0], chooseLevel(0, false, pixels, kBelow, 0.1f)) << pixels;
        }
        crossfading += blend.crossfading();
    }
    EXPECT_GT(crossfading, 300);
    // Halfway at the threshold itself.
    EXPECT_NEAR(scene::crossfadeLevels(60.0f, kBelow, 0.1f).coarserWeight, 0.5f, 1e-5f);
    EXPECT_EQ(scene::crossfadeLevels(60.0f, kBelow, 0.1f).levels, (std::array<int, 2>{0, 1}));
}

// The committed broadleaf tree at three distances, seen by a 720-line view.
struct TreeRow {
    std::unique_ptr<render::Device> backend = render::soft::createSoftBackend({1, 64, false});
    scene::MeshLibrary library{*backend};
    ecs::Registry registry;
    std::filesystem::path file = racer::defaultContentDir() / "models" / "tree_broadleaf.glb";
    scene::ModelId full = racer::loadContentModel(library, file);
    scene::LevelsOfDetail levels = racer::loadPlantLevels(library, racer::defaultContentDir(), file, full);
    glm::mat4 projection = render::perspectiveReverseZ(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 30000.0f);
    float focal = scene::focalPixels(projection, 720);

    // A tree whose height on screen is `pixels`, straight ahead.
    void plantAt(float pixels) {
        racer::placeModel(registry, full, {0.0f, 0.0f, levels.height * focal / pixels}, 0.0f, 1.0f);
    }
    scene::DrawLists extract() {
        const glm::mat4 view = glm::lookAt(glm::vec3(0, 4, 0), glm::vec3(0, 4, 1), glm::vec3(0, 1, 0));
        return scene::extractDrawLists(registry, library, projection * view, glm::vec3(0, 4, 0));
    }
};

TEST(LevelsOfDetail, CommittedPlantsSwitchByHeightOnScreen) {
    TreeRow row;
    ASSERT_EQ(row.levels.levels, 3);
    const float near = 2.0f * row.levels.belowPixels[0],
                middle = 0.5f * (row.levels.belowPixels[0] + row.levels.belowPixels[1]),
                far = 0.5f * row.levels.belowPixels[1];
    ASSERT_GT(row.levels.belowPixels[0], row.levels.belowPixels[1]) << "the broadleaf tree has a middle level";
    for (float pixels : {near, middle, far}) row.plantAt(pixels);
    // Without levels: every tree the full model, no counts.
    const scene::DrawLists plain = row.extract();
    EXPECT_EQ(plain.instancesAtLevel, (std::array<std::uint32_t, 3>{0, 0, 0}));
    racer::attachPlantLevels(row.registry, {{row.full, row.levels}});
    // Levels attached but none chosen: still the full model everywhere, the same batches.
    const scene::DrawLists unchosen = row.extract();
    EXPECT_EQ(unchosen.instancesAtLevel, (std::array<std::uint32_t, 3>{3, 0, 0}));
    ASSERT_EQ(unchosen.mask.size(), plain.mask.size());
    for (std::size_t i = 0; i < plain.mask.size(); ++i) {
        EXPECT_EQ(unchosen.mask[i].part, plain.mask[i].part);
        EXPECT_EQ(unchosen.mask[i].instances.size(), plain.mask[i].instances.size());
    }
    scene::selectLevelsOfDetail(row.registry, row.library, {glm::vec3(0, 4, 0), row.focal});
    const scene::DrawLists lists = row.extract();
    EXPECT_EQ(lists.instancesAtLevel, (std::array<std::uint32_t, 3>{1, 1, 1}));
    // One foliage batch per level, each drawing that level's own part.
    ASSERT_EQ(lists.mask.size(), 3u);
    for (int level = 0; level < 3; ++level) {
        const std::vector<std::uint32_t>& parts = row.library.partsOf(row.levels.models[std::size_t(level)]);
        const auto drawn = std::count_if(lists.mask.begin(), lists.mask.end(), [&](const scene::DrawBatch& b) {
            return std::find(parts.begin(), parts.end(), b.part) != parts.end() && b.instances.size() == 1;
        });
        EXPECT_EQ(drawn, 1) << "level " << level;
    }
    // The impostor has no trunk: two opaque batches (the near and middle trunks).
    EXPECT_EQ(lists.opaque.size(), 2u);
}

// With a crossfade band, a tree at its first threshold draws the full model and the middle
// level, each instance's tint alpha its weight (one half each); without one, one level.
TEST(LevelsOfDetail, ExtractionDrawsBothLevelsOfACrossfadeWithTheirWeights) {
    TreeRow row;
    row.plantAt(row.levels.belowPixels[0] * 1.02f);
    racer::attachPlantLevels(row.registry, {{row.full, row.levels}});
    scene::selectLevelsOfDetail(row.registry, row.library, {glm::vec3(0, 4, 0), row.focal, 0.1f, 0.1f});
    const scene::DrawLists lists = row.extract();
    EXPECT_EQ(lists.instancesAtLevel, (std::array<std::uint32_t, 3>{1, 1, 0}));
    std::array<float, 2> weight{};
    for (const scene::DrawBatch& b : lists.mask)
        for (int level = 0; level < 2; ++level) {
            const auto& parts = row.library.partsOf(row.levels.models[std::size_t(level)]);
            if (std::find(parts.begin(), parts.end(), b.part) == parts.end()) continue;
            ASSERT_EQ(b.instances.size(), 1u);
            EXPECT_EQ(b.level, level);
            EXPECT_TRUE(b.crossfading);
            weight[std::size_t(level)] = b.instances[0].tint.a;
            EXPECT_EQ(glm::vec3(b.instances[0].tint), glm::vec3(1.0f)) << "only the alpha carries the weight";
        }
    // 2 % above the threshold in a band of 10 % either side (the height measured to the crown's
    // centre, not straight ahead: a little off 0.4).
    EXPECT_NEAR(weight[1], 0.4f, 0.01f);
    EXPECT_FLOAT_EQ(weight[0] + weight[1], 1.0f);
    scene::selectLevelsOfDetail(row.registry, row.library, {glm::vec3(0, 4, 0), row.focal, 0.1f, 0.0f});
    EXPECT_EQ(row.extract().instancesAtLevel, (std::array<std::uint32_t, 3>{1, 0, 0})) << "no band: the level kept";
}

// A crossfading plant's instances are batched apart from the steady plants of the same level
// (after them), so the techniques that dither draw only those: DrawBatch::crossfading.
TEST(LevelsOfDetail, CrossfadingInstancesHaveBatchesOfTheirOwn) {
    TreeRow row;
    row.plantAt(row.levels.belowPixels[0] * 1.02f);  // in the band: levels 0 and 1
    // Level 1, steady: between the two thresholds, outside both bands.
    row.plantAt(0.5f * (row.levels.belowPixels[0] * 0.85f + row.levels.belowPixels[1] * 1.15f));
    racer::attachPlantLevels(row.registry, {{row.full, row.levels}});
    scene::selectLevelsOfDetail(row.registry, row.library, {glm::vec3(0, 4, 0), row.focal, 0.1f, 0.1f});
    const scene::DrawLists lists = row.extract();
    const auto& levelOne = row.library.partsOf(row.levels.models[1]);
    int steady = 0, fading = 0;
    for (std::size_t i = 0; i < lists.mask.size(); ++i) {
        const scene::DrawBatch& b = lists.mask[i];
        if (std::find(levelOne.begin(), levelOne.end(), b.part) == levelOne.end()) continue;
        EXPECT_EQ(b.level, 1);
        ASSERT_EQ(b.instances.size(), 1u);
        EXPECT_EQ(b.instances[0].tint.a < 1.0f, b.crossfading);
        (b.crossfading ? fading : steady) += 1;
        if (b.crossfading) {  // right after its part's steady batch
            ASSERT_GT(i, 0u);
            EXPECT_EQ(lists.mask[i - 1].part, b.part);
            EXPECT_FALSE(lists.mask[i - 1].crossfading);
        }
    }
    EXPECT_GT(steady, 0);
    EXPECT_EQ(fading, steady);  // each level-1 part: one steady batch, one crossfading
}

// The band damps motion only: the same height on screen reached by moving keeps the level,
// reached by a new focal length (a resized frame) is chosen afresh, as a run at that size would.
TEST(LevelsOfDetail, ANewViewChoosesAfresh) {
    TreeRow row;
    row.plantAt(1.5f * row.levels.belowPixels[0]);
    racer::attachPlantLevels(row.registry, {{row.full, row.levels}});
    auto levelFor = [&](float focal) {
        scene::selectLevelsOfDetail(row.registry, row.library, {glm::vec3(0, 4, 0), focal});
        return row.extract().instancesAtLevel;
    };
    EXPECT_EQ(levelFor(row.focal), (std::array<std::uint32_t, 3>{1, 0, 0}));
    // 0.95 of the threshold, inside the band: a fresh choice takes the middle level.
    const float resized = row.focal * 0.95f / 1.5f;
    EXPECT_EQ(levelFor(resized), (std::array<std::uint32_t, 3>{0, 1, 0}));
    // Back at the first focal, then moved (same focal) to that height: the band keeps level 0.
    EXPECT_EQ(levelFor(row.focal), (std::array<std::uint32_t, 3>{1, 0, 0}));
    row.registry.view<scene::Transform>().each([&](scene::Transform& t) { t.position.z *= 1.5f / 0.95f; });
    EXPECT_EQ(levelFor(row.focal), (std::array<std::uint32_t, 3>{1, 0, 0}));
}

// racer's frame with levels on: the dump's label and the HUD line count each level's plants,
// as extraction counted them; with levels off neither says anything of levels.
TEST(LevelsOfDetail, FrameGraphDumpCountsEachLevel) {
    for (bool lod : {true, false}) {
        SCOPED_TRACE(lod ? "lod on" : "lod off");
        auto backend = render::soft::createSoftBackend({1, 64, false});
        racer::RacingScene scene(*backend, racer::SceneOptions{racer::defaultContentDir(), 1, {}, lod});
        racer::RendererOptions options;
        options.width = 160;
        options.height = 90;
        racer::FrameRenderer renderer(*backend, scene.library(), options);
        const racer::CameraView view =
            racer::cameraView(racer::CameraMode::Chase, scene, 0.0f, 16.0f / 9.0f, racer::FreeCamera{});
        if (lod)
            scene::selectLevelsOfDetail(scene.registry(), scene.library(),
                                        {view.eye, scene::focalPixels(view.projection, options.height)});
        const scene::DrawLists lists =
            scene::extractDrawLists(scene.registry(), scene.library(), view.viewProj, view.eye);
        renderer.render(lists, view);
        std::ostringstream dot;
        renderer.dumpGraph(dot);
        const auto& n = lists.instancesAtLevel;
        if (!lod) {
            EXPECT_EQ(n[0] + n[1] + n[2], 0u);
            EXPECT_EQ(dot.str().find("levels of detail"), std::string::npos);
            EXPECT_EQ(racer::lodCountsLine(lists), "");
            continue;
        }
        EXPECT_GT(n[0], 0u);
        EXPECT_GT(n[2], n[0]) << "most of the lap's plants are far from the chase camera";
        const std::string line = "levels of detail: " + std::to_string(n[0]) + " full, " + std::to_string(n[1]) +
                                 " middle, " + std::to_string(n[2]) + " impostor";
        EXPECT_EQ(racer::lodCountsLine(lists), line);
        EXPECT_NE(dot.str().find(line + "\\l"), std::string::npos) << dot.str();
        racer::HudFacts facts;
        facts.frameMs = 10.0;
        facts.levelsOfDetail = racer::lodCountsLine(lists);
        const std::vector<std::string> hud = racer::hudLines(facts);
        EXPECT_NE(std::find(hud.begin(), hud.end(), line), hud.end());
    }
}

}  // namespace
