// SPDX-License-Identifier: MIT
#include "racing_scene.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

#include <glm/gtc/quaternion.hpp>

#include "engine/assets/gltf.hpp"
#include "engine/assets/image.hpp"
#include "engine/assets/mips.hpp"
#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/scene/components.hpp"
#include "content_files.hpp"
#include "track_ground.hpp"

namespace racer {

using namespace engine;
using namespace engine::render;
using scene::Transform;

namespace {

glm::quat yaw(float radians) { return glm::angleAxis(radians, glm::vec3(0.0f, 1.0f, 0.0f)); }

}  // namespace

RacingScene::RacingScene(Backend& backend, const SceneOptions& options)
    : library_(backend), track_(options.seed) {
    const std::filesystem::path& content = options.contentDir;
    Random random(options.seed);

    // Ground and road, built from the same height field the track follows.
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    buildTerrain(2000.0f, 160, vertices, indices);
    scene::PartMaterial ground;
    ground.doubleSided = true;
    ground.baseColor = loadContentTexture(backend, content / "textures" / "ground.png");
    placeModel(registry_, library_.add("terrain", vertices, indices, ground), {}, 0.0f, 1.0f);
    vertices.clear();
    indices.clear();
    track_.buildRoad(vertices, indices);
    scene::PartMaterial road;
    road.doubleSided = true;
    road.baseColor = loadContentTexture(backend, content / "textures" / "track.png");
    placeModel(registry_, library_.add("road", vertices, indices, road), {}, 0.0f, 1.0f);

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

    // Each draw from `random` is sequenced on its own: C++ leaves the evaluation order of a
    // call's arguments (and of most operators' operands) unspecified, GCC goes right to left
    // and Clang left to right, so two draws in one expression grow a different forest per
    // compiler. The order kept is the one GCC gave the goldens: scale, heading, then position.
    // Trees and bushes line the track on both sides, clear of the road.
    auto besideTrack = [&](float minOffset, float maxOffset) {
        const float d = random.uniform(0.0f, track_.length());
        const glm::vec3 p = track_.position(d), f = track_.forward(d);
        const glm::vec3 side = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
        const float distance = random.uniform(minOffset, maxOffset);
        const float offset = random.next() & 1 ? distance : -distance;
        glm::vec3 q = p + side * offset;
        q.y = terrainHeight(q.x, q.z);
        return q;
    };
    for (int i = 0; i < options.trees; ++i) {
        const scene::ModelId m = trees[random.next() % trees.size()];
        const float scale = random.uniform(0.8f, 1.3f), heading = random.uniform(0.0f, 6.2832f);
        placeModel(registry_, m, besideTrack(track_.width() * 0.5f + 3.0f, 45.0f), heading, scale);
    }
    for (int i = 0; i < options.bushes; ++i) {
        const scene::ModelId m = bushes[random.next() % bushes.size()];
        const float scale = random.uniform(0.7f, 1.4f), heading = random.uniform(0.0f, 6.2832f);
        placeModel(registry_, m, besideTrack(track_.width() * 0.5f + 1.0f, 25.0f), heading, scale);
    }
    // A grove across the track from the start line, where the pre-race pan camera looks:
    // overlapping trees close up, the case where alpha testing sparkles ([Hathaway 2010] §3.4).
    {
        const glm::vec3 start = track_.position(0.0f), f = track_.forward(0.0f);
        const glm::vec3 side = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
        for (int i = 0; i < options.groveTrees; ++i) {
            const float along = random.uniform(-30.0f, 30.0f);
            const float across = random.uniform(track_.width() * 0.5f + 6.0f, 40.0f);
            glm::vec3 p = start + side * across + f * along;
            p.y = terrainHeight(p.x, p.z);
            const bool tree = (random.next() % 3) != 0;
            const auto& models = tree ? trees : bushes;
            const float scale = random.uniform(0.9f, 1.4f), heading = random.uniform(0.0f, 6.2832f);
            placeModel(registry_, models[random.next() % models.size()], p, heading, scale);
        }
    }
    // The vista: a ring of forest out to a few kilometres ([Hathaway 2010] §3.1).
    for (int i = 0; i < options.vistaTrees; ++i) {
        const float angle = random.uniform(0.0f, 2.0f * std::numbers::pi_v<float>);
        const float radius = random.uniform(450.0f, 1900.0f);
        glm::vec3 p(radius * std::cos(angle), 0.0f, radius * std::sin(angle));
        p.y = terrainHeight(p.x, p.z);
        const float scale = random.uniform(1.5f, 2.5f), heading = random.uniform(0.0f, 6.2832f);
        placeModel(registry_, trees[random.next() % trees.size()], p, heading, scale);
    }

    // Water pools (glTF BLEND material): one among the grove's trees, the rest in the infield.
    const scene::ModelId water = loadContentModel(library_, content / "models" / "water.glb");
    {
        const glm::vec3 start = track_.position(0.0f), f = track_.forward(0.0f);
        const glm::vec3 side = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
        glm::vec3 p = start + side * (track_.width() * 0.5f + 9.0f) - f * 4.0f;
        p.y = terrainHeight(p.x, p.z) + 0.3f;
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
        p.y = terrainHeight(p.x, p.z) + 0.3f;
        const float scale = random.uniform(2.0f, 3.5f), heading = random.uniform(0.0f, 6.2832f);
        placeModel(registry_, water, p, heading, scale);
    }

    const scene::ModelId carModel = loadContentModel(library_, content / "models" / "car.glb");
    car_ = registry_.create();
    registry_.add<Transform>(car_);
    registry_.add<scene::Renderable>(car_, scene::Renderable{carModel});
    registry_.add<scene::Collider>(car_, scene::Collider{2.5f});
    registry_.add<Car>(car_);
    update(0.0f);
    log::info("racing scene: ", registry_.size(), " entities, ", library_.partCount(), " mesh parts, track ",
              int(track_.length()), " m");
}

void RacingScene::update(float dt) {
    Car& car = registry_.get<Car>(car_);
    Transform& t = registry_.get<Transform>(car_);
    if (car.driven) {
        car.motion = driveStep(car.motion, controls_, dt,
                               [this](float x, float z) { return groundHeight(track_, x, z); });
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
