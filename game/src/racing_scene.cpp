// SPDX-License-Identifier: MIT
#include "racing_scene.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <glm/gtc/quaternion.hpp>

#include "engine/assets/gltf.hpp"
#include "engine/assets/image.hpp"
#include "engine/assets/mips.hpp"
#include "engine/scene/rigid_motion.hpp"
#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/scene/components.hpp"
#include "content_files.hpp"
#include "plant_levels.hpp"
#include "track_ground.hpp"

namespace racer {

using namespace engine;
using namespace engine::render;
using scene::Transform;

namespace {

glm::quat yaw(float radians) { return glm::angleAxis(radians, glm::vec3(0.0f, 1.0f, 0.0f)); }

}  // namespace

RacingScene::RacingScene(Backend& backend, const SceneOptions& options)
    : library_(backend), track_(options.seed), ground_(track_) {
    const std::filesystem::path& content = options.contentDir;
    Random random(options.seed);

    // The ground in chunks (each culled on its own), the road and its gravel shoulders.
    scene::PartMaterial groundMaterial;
    groundMaterial.doubleSided = true;
    groundMaterial.baseColor = loadContentTexture(backend, content / "textures" / "ground.png");
    const std::vector<GroundChunk> chunks = ground_.buildChunks();
    for (std::size_t i = 0; i < chunks.size(); ++i)
        placeModel(registry_,
                   library_.add("ground " + std::to_string(i), chunks[i].vertices, chunks[i].indices, groundMaterial),
                   {}, 0.0f, 1.0f);
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    track_.buildRoad(vertices, indices);
    scene::PartMaterial road;
    road.doubleSided = true;
    road.baseColor = loadContentTexture(backend, content / "textures" / "track.png");
    placeModel(registry_, library_.add("road", vertices, indices, road), {}, 0.0f, 1.0f);
    vertices.clear();
    indices.clear();
    track_.buildShoulders(Ground::kCorridorDrop, vertices, indices);
    scene::PartMaterial shoulder = road;  // the asphalt's grit, tinted to gravel
    shoulder.baseColorFactor = {1.45f, 1.2f, 0.85f, 1.0f};
    placeModel(registry_, library_.add("shoulders", vertices, indices, shoulder), {}, 0.0f, 1.0f);

    // Foliage models: every tree_*/bush_* file in content/models, in name order.
    std::vector<std::filesystem::path> treeFiles, bushFiles;
    for (const auto& entry : std::filesystem::directory_iterator(requireContent(content / "models"))) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("tree", 0) == 0) treeFiles.push_back(entry.path());
        if (name.rfind("bush", 0) == 0) bushFiles.push_back(entry.path());
    }
    std::sort(treeFiles.begin(), treeFiles.end());
    std::sort(bushFiles.begin(), bushFiles.end());
    if (treeFiles.empty() || bushFiles.empty())
        throw Error("no tree*/bush* models in '" + (content / "models").string() + "'");
    std::vector<scene::ModelId> trees, bushes;
    for (const auto& f : treeFiles) trees.push_back(loadContentModel(library_, f));
    for (const auto& f : bushFiles) bushes.push_back(loadContentModel(library_, f));
    // Every draw from `random` (here and in plantForest) is a statement of its own: C++ leaves
    // the evaluation order of a call's arguments unspecified (GCC right to left, Clang left to
    // right), so two draws in one expression would grow a different scene per compiler.
    plantForest(registry_, track_, ground_, trees, bushes, random, options.forest);
    if (options.levelsOfDetail) {
        std::map<scene::ModelId, scene::LevelsOfDetail> levels;
        for (std::size_t i = 0; i < treeFiles.size(); ++i)
            levels[trees[i]] = loadPlantLevels(library_, content, treeFiles[i], trees[i]);
        for (std::size_t i = 0; i < bushFiles.size(); ++i)
            levels[bushes[i]] = loadPlantLevels(library_, content, bushFiles[i], bushes[i]);
        attachPlantLevels(registry_, levels);
    }

    // Water pools (glTF BLEND material): one among the grove's trees, the rest in the infield.
    const scene::ModelId water = loadContentModel(library_, content / "models" / "water.glb");
    {
        const glm::vec3 start = track_.position(0.0f), f = track_.forward(0.0f);
        const glm::vec3 side = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
        glm::vec3 p = start + side * (track_.width() * 0.5f + 9.0f) - f * 4.0f;
        p.y = ground_.height(p.x, p.z) + 0.3f;
        placeModel(registry_, water, p, 0.0f, 2.2f);

        // The sun 17 degrees above the horizon, straight behind the grove from the start line.
        const float elevation = glm::radians(17.0f);
        sun_.towardLight = side * std::cos(elevation) + glm::vec3(0.0f, std::sin(elevation), 0.0f);
        sun_.color = {1.15f, 0.98f, 0.80f};
        sun_.ambient = {0.34f, 0.37f, 0.45f};
    }
    for (int i = 0; i < 4; ++i) {
        const float angle = float(i) * 1.5708f + 0.4f;
        glm::vec3 p(95.0f * std::cos(angle), 0.0f, 95.0f * std::sin(angle));
        p.y = ground_.height(p.x, p.z) + 0.3f;
        const float scale = random.uniform(2.0f, 3.5f), heading = random.uniform(0.0f, 6.2832f);
        placeModel(registry_, water, p, heading, scale);
    }

    const scene::ModelId carModel = loadContentModel(library_, content / "models" / "car.glb");
    car_ = registry_.create();
    registry_.add<Transform>(car_);
    registry_.add<scene::Renderable>(car_, scene::Renderable{carModel});
    registry_.add<scene::Collider>(car_, scene::Collider{2.5f});
    registry_.add<Car>(car_);
    registry_.add<scene::MovesRigidly>(car_);  // its motion vectors (engine/scene rigid_motion.hpp)
    update(0.0f);
    log::info("racing scene: ", registry_.size(), " entities, ", library_.partCount(), " mesh parts, track ",
              int(track_.length()), " m");
}

void RacingScene::update(float dt) {
    Car& car = registry_.get<Car>(car_);
    Transform& t = registry_.get<Transform>(car_);
    if (car.driven) {
        car.motion = driveStep(car.motion, controls_, dt,
                               [this](float x, float z) { return groundHeight(track_, ground_, x, z); });
        car.position = t.position = car.motion.position;
        car.forward = headingDirection(car.motion.heading);
        // Pitched about its own x axis, nose up on a rising slope.
        t.rotation = yaw(car.motion.heading) * glm::angleAxis(-car.motion.pitch, glm::vec3(1.0f, 0.0f, 0.0f));
        return;
    }
    car.distance += car.speed * dt;
    t.position = car.position = track_.position(car.distance);
    const glm::vec3 f = car.forward = track_.forward(car.distance);
    t.rotation = yaw(std::atan2(f.x, f.z));
}

void RacingScene::takeWheel(const DriveControls& controls) {
    Car& car = registry_.get<Car>(car_);
    controls_ = controls;
    if (car.driven) return;
    car.driven = true;
    car.motion = CarMotion{car.position, std::atan2(car.forward.x, car.forward.z), car.speed, 0.0f};
}

void RacingScene::engageAutopilot() {
    Car& car = registry_.get<Car>(car_);
    if (!car.driven) return;
    car.driven = false;
    controls_ = {};
    car.distance = nearestTrackDistance(track_, car.position.x, car.position.z);
    update(0.0f);
}

}  // namespace racer
