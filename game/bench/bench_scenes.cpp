// SPDX-License-Identifier: MIT
#include "bench_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/assets/gltf.hpp"
#include "engine/assets/image.hpp"
#include "engine/assets/mips.hpp"
#include "engine/core/error.hpp"
#include "engine/render/projection.hpp"
#include "engine/scene/components.hpp"
#include "engine/scene/rigid_motion.hpp"
#include "content_files.hpp"
#include "plant_levels.hpp"
#include "track.hpp"  // terrainHeight, buildTerrain, Random: the racer's ground and placement PRNG

namespace bench {

using namespace engine;
using namespace engine::render;

namespace {

constexpr float kFovY = 1.04719755f;  // 60°, as the racer's cameras
constexpr float kNear = 0.1f;
constexpr float kFar = 30000.0f;

struct SceneEntry {
    SceneKind kind;
    const char* name;
};
constexpr SceneEntry kScenes[] = {
    {SceneKind::Tree, "tree"}, {SceneKind::Forest, "forest"}, {SceneKind::Vista, "vista"}, {SceneKind::Empty, "empty"}};

glm::vec3 onGround(float x, float z) { return {x, racer::terrainHeight(x, z), z}; }

// tan(kFovY / 2), the same in every build: at -O2 GCC folds std::tan of this constant to the
// correctly rounded float, while a Debug build calls glibc's tanf, which is one ulp away for
// this angle. The tangent taken in double and rounded once is the correctly rounded float in both.
float halfFovTangent() { return static_cast<float>(std::tan(0.5 * static_cast<double>(kFovY))); }

}  // namespace

const std::vector<SceneKind>& allScenes() {
    static const std::vector<SceneKind> all{SceneKind::Tree, SceneKind::Forest, SceneKind::Vista, SceneKind::Empty};
    return all;
}

const char* sceneName(SceneKind kind) {
    if (kind == SceneKind::Layers) return "layers";  // not in kScenes: --scenes does not offer it
    for (const SceneEntry& s : kScenes)
        if (s.kind == kind) return s.name;
    return "?";
}

bool parseScene(std::string_view name, SceneKind& kind) {
    for (const SceneEntry& s : kScenes)
        if (name == s.name) {
            kind = s.kind;
            return true;
        }
    return false;
}

BenchScene::BenchScene(Backend& backend, SceneKind kind, const std::filesystem::path& contentDir)
    : kind_(kind), library_(backend), contentDir_(contentDir) {
    const std::filesystem::path models = contentDir / "models";
    auto model = [&](const char* file) {
        plants_.emplace_back(racer::loadContentModel(library_, models / file), file);
        return plants_.back().first;
    };
    const scene::ModelId broadleaf = model("tree_broadleaf.glb");
    const scene::ModelId tall = model("tree_tall.glb");
    const scene::ModelId palm = model("tree_palm.glb");
    const scene::ModelId fern = model("bush_fern.glb");
    const scene::ModelId round = model("bush_round.glb");
    const scene::ModelId trees[] = {broadleaf, tall, palm};
    const scene::ModelId bushes[] = {fern, round};
    racer::Random random(0x55A3u + static_cast<unsigned>(kind));  // fixed: every run builds the same scene

    // Ground: the racer's rolling terrain, as large as the view needs.
    const float groundHalf = kind == SceneKind::Vista ? 2000.0f : 300.0f;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    racer::buildTerrain(groundHalf, kind == SceneKind::Vista ? 160 : 60, vertices, indices);
    scene::PartMaterial ground;
    ground.doubleSided = true;
    ground.baseColor = racer::loadContentTexture(backend, contentDir / "textures" / "ground.png");
    groundTexture_ = ground.baseColor.texture;
    racer::placeModel(registry_, library_.add("terrain", vertices, indices, ground), {}, 0.0f, 1.0f);

    auto randomYaw = [&] { return random.uniform(0.0f, 2.0f * std::numbers::pi_v<float>); };
    // Each draw from `random` is sequenced on its own: C++ leaves the evaluation order of a
    // call's arguments unspecified (GCC right to left, Clang left to right), so draws made in
    // one call would build a different scene per compiler. The order kept is GCC's: scale,
    // heading, then the model.
    switch (kind) {
        case SceneKind::Tree: {
            // The crown (upper 60% of the bounds) fills the frame's height, seen level.
            const glm::vec3 base = onGround(0.0f, 0.0f);
            racer::placeModel(registry_, broadleaf, base, 0.6f, 1.0f);
            const scene::Aabb b = library_.bounds(broadleaf);
            const float height = 0.6f * (b.max.y - b.min.y);
            const glm::vec3 centre =
                base + glm::vec3(0.5f * (b.min.x + b.max.x), b.max.y - 0.5f * height, 0.5f * (b.min.z + b.max.z));
            const float distance = 0.5f * height / halfFovTangent();
            target_ = centre;
            eye_ = centre - glm::vec3(0.0f, 0.0f, distance);
            eye_.y = std::max(eye_.y, racer::terrainHeight(eye_.x, eye_.z) + 1.5f);
            // Half a pixel of a 720-line frame per pan frame at the tree's distance.
            panStep_ = 0.5f * distance * 2.0f * halfFovTangent() / 720.0f;
            break;
        }
        case SceneKind::Forest: {
            // A jittered grid of trees 4 m apart with bushes between, seen from just outside
            // its edge: every pixel above the ground is covered by several trees.
            for (int i = 0; i < 22; ++i)
                for (int j = 0; j < 22; ++j) {
                    const float x = -42.0f + 4.0f * float(i) + random.uniform(-1.5f, 1.5f);
                    const float z = 5.0f + 4.0f * float(j) + random.uniform(-1.5f, 1.5f);
                    const float scale = random.uniform(0.9f, 1.4f), heading = randomYaw();
                    racer::placeModel(registry_, trees[random.next() % 3], onGround(x, z), heading, scale);
                }
            for (int i = 0; i < 160; ++i) {
                const float x = random.uniform(-45.0f, 45.0f), z = random.uniform(3.0f, 95.0f);
                const float scale = random.uniform(0.8f, 1.4f), heading = randomYaw();
                racer::placeModel(registry_, bushes[random.next() % 2], onGround(x, z), heading, scale);
            }
            eye_ = onGround(0.0f, -4.0f) + glm::vec3(0.0f, 1.8f, 0.0f);
            target_ = onGround(0.0f, 30.0f) + glm::vec3(0.0f, 8.0f, 0.0f);  // into the canopies
            panStep_ = 0.5f * 15.0f * 2.0f * halfFovTangent() / 720.0f;     // half a pixel at 15 m
            break;
        }
        case SceneKind::Vista: {
            // Hundreds of trees from 120 m to 1.5 km in front of a raised viewpoint.
            for (int i = 0; i < 700; ++i) {
                const float angle = random.uniform(-0.75f, 0.75f);
                const float radius = random.uniform(120.0f, 1500.0f);
                const float scale = random.uniform(1.5f, 2.5f), heading = randomYaw();
                racer::placeModel(registry_, trees[random.next() % 3],
                                  onGround(radius * std::sin(angle), radius * std::cos(angle)), heading, scale);
            }
            eye_ = onGround(0.0f, 0.0f) + glm::vec3(0.0f, 45.0f, 0.0f);
            target_ = onGround(0.0f, 600.0f) + glm::vec3(0.0f, 10.0f, 0.0f);
            break;
        }
        case SceneKind::Layers: throw Error("the layers scene is built from its layer count, not by kind");
        case SceneKind::Empty: {
            // Foliage exists but only behind the camera: extraction culls it, so every
            // technique should cost what the opaque frame costs (its passes are empty).
            for (int i = 0; i < 40; ++i) {
                const float x = random.uniform(-60.0f, 60.0f), z = random.uniform(-90.0f, -25.0f);
                const float scale = random.uniform(0.9f, 1.4f), heading = randomYaw();
                racer::placeModel(registry_, trees[random.next() % 3], onGround(x, z), heading, scale);
            }
            eye_ = onGround(0.0f, 0.0f) + glm::vec3(0.0f, 2.0f, 0.0f);
            target_ = onGround(0.0f, 80.0f) + glm::vec3(0.0f, 2.0f, 0.0f);
            break;
        }
    }
}

BenchScene::BenchScene(Backend& backend, int cardLayers, const std::filesystem::path& contentDir)
    : kind_(SceneKind::Layers), library_(backend) {
    if (cardLayers < 1) throw Error("layers scene: " + std::to_string(cardLayers) + " card layers (at least 1)");
    // The fern's leaf material (alpha-masked, its texture with the library's coverage-keeping mips).
    const scene::ModelId fern = racer::loadContentModel(library_, contentDir / "models" / "bush_fern.glb");
    const scene::PartMaterial* leaves = nullptr;
    for (std::uint32_t part : library_.partsOf(fern))
        if (library_.part(part).material.surface == scene::SurfaceClass::Mask) leaves = &library_.part(part).material;
    if (!leaves) throw Error("layers scene: bush_fern.glb has no alpha-masked part");
    // A unit card in the XY plane facing the camera, its texture repeated 4 x 4 times.
    std::vector<Vertex> vertices(4);
    const glm::vec2 corners[4] = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}, {-0.5f, 0.5f}};
    for (int i = 0; i < 4; ++i) {
        vertices[i].position = {corners[i].x, corners[i].y, 0.0f};
        vertices[i].normal = {0.0f, 0.0f, -1.0f};
        vertices[i].uv = {4.0f * (corners[i].x + 0.5f), 4.0f * (0.5f - corners[i].y)};
    }
    const std::vector<std::uint32_t> indices{0, 1, 2, 0, 2, 3};
    scene::PartMaterial card = *leaves;
    card.doubleSided = true;
    const scene::ModelId model = library_.add("leaf card", vertices, indices, card);
    // Cards from 3 m away, 0.25 m apart, each scaled to cover the widest (21:9) view at its
    // distance, shifted sideways so the leaves of successive cards do not line up.
    eye_ = {0.0f, 0.0f, 0.0f};
    target_ = {0.0f, 0.0f, 1.0f};
    racer::Random random(0x1A7E5u);
    for (int i = 0; i < cardLayers; ++i) {
        const float distance = 3.0f + 0.25f * float(i);
        const float shift = random.uniform(-0.5f, 0.5f) * distance;
        const float size = 2.5f * distance * 2.0f * halfFovTangent() + 2.0f * std::abs(shift);
        racer::placeModel(registry_, model, {shift, 0.0f, distance}, 0.0f, size);
    }
}

BenchScene::~BenchScene() {
    if (groundTexture_) library_.backend().destroy(groundTexture_);
}

void BenchScene::useLevelsOfDetail(int viewportHeight, float crossfade) {
    if (lodViewportHeight_ == 0) {
        std::map<scene::ModelId, scene::LevelsOfDetail> levels;
        for (const auto& [model, file] : plants_)
            levels[model] = racer::loadPlantLevels(library_, contentDir_, contentDir_ / "models" / file, model);
        racer::attachPlantLevels(registry_, levels);
    }
    lodViewportHeight_ = viewportHeight;
    lodCrossfade_ = crossfade;
}

engine::ecs::Entity BenchScene::addCar() {
    if (!hasCar()) throw engine::Error(std::string("ssam-bench: the ") + sceneName(kind_) + " scene has no car");
    const scene::ModelId model = racer::loadContentModel(library_, contentDir_ / "models" / "car.glb");
    const engine::ecs::Entity car = registry_.create();
    registry_.add<scene::Transform>(car);
    registry_.add<scene::Renderable>(car, scene::Renderable{model});
    registry_.add<scene::MovesRigidly>(car);
    placeCar(car, 0);
    return car;
}

void BenchScene::placeCar(engine::ecs::Entity car, int frame) {
    const glm::vec3 ahead = glm::normalize(glm::vec3(target_.x - eye_.x, 0.0f, target_.z - eye_.z));
    const glm::vec3 right = glm::normalize(glm::cross(ahead, glm::vec3(0.0f, 1.0f, 0.0f)));
    glm::vec3 p = eye_ + 6.0f * ahead + right * (kCarStep * float(frame) - 4.0f);
    p.y = racer::terrainHeight(p.x, p.z);
    scene::Transform& t = registry_.get<scene::Transform>(car);
    t.position = p;
    t.rotation = glm::angleAxis(std::atan2(right.x, right.z), glm::vec3(0.0f, 1.0f, 0.0f));  // facing its way
}

BenchCamera BenchScene::dollyCamera(float aspect, int frame) const {
    return view(aspect, 0.0f, kDollyLength - kDollyStep * float(frame));
}

BenchCamera BenchScene::view(float aspect, float sideways, float back) const {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const glm::vec3 right = glm::normalize(glm::cross(target_ - eye_, up));
    glm::vec3 shift = right * sideways;
    if (back != 0.0f) {
        // Back along the view's ground direction, the eye kept as high above the terrain.
        const glm::vec3 ahead = glm::normalize(glm::vec3(target_.x - eye_.x, 0.0f, target_.z - eye_.z));
        const glm::vec3 eye = eye_ - ahead * back;
        const float lift = racer::terrainHeight(eye.x, eye.z) - racer::terrainHeight(eye_.x, eye_.z);
        shift += eye - eye_ + glm::vec3(0.0f, lift, 0.0f);
    }
    BenchCamera c;
    c.eye = eye_ + shift;
    const glm::mat4 projection = perspectiveReverseZ(kFovY, aspect, kNear, kFar);
    c.viewProj = projection * glm::lookAt(c.eye, target_ + shift, up);
    if (lodViewportHeight_ > 0) c.focalPixels = scene::focalPixels(projection, lodViewportHeight_);
    c.crossfade = lodCrossfade_;
    return c;
}

}  // namespace bench
