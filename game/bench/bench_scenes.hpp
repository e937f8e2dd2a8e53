// SPDX-License-Identifier: MIT
#pragma once
// The scenes `ssam-bench` measures every transparency technique on, built from content/models
// with the engine's ECS (Transform + Renderable entities, a MeshLibrary) so extraction and
// culling are the racer's own:
//   tree    one tree close up: the paper's "high degree of depth complexity present within a
//           single foliage model" ([Hathaway 2010] §3.3)
//   forest  a dense stand seen from inside its edge: many overlapping trees and bushes
//   vista   a distant view over hundreds of trees ([Hathaway 2010] §3.1: Pure's vistas)
//   empty   trees only behind the camera: no foliage in view, the opaque frame alone
//   layers  (--scaling only) N full-view cards of fern leaves stacked in front of the camera:
//           foliage depth complexity N where the leaves cover
// Projection: reverse-Z, 60° vertical field of view, 0.1 m to 30 km, depth test Greater —
// the racer's conventions (game/src/camera_rig.cpp, frame_renderer.cpp).
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/ecs/registry.hpp"
#include "engine/render/backend.hpp"
#include "engine/scene/mesh_library.hpp"

namespace bench {

enum class SceneKind { Tree, Forest, Vista, Empty, Layers };

// tree, forest, vista, empty: in the order tables list them.
const std::vector<SceneKind>& allScenes();
const char* sceneName(SceneKind kind);
bool parseScene(std::string_view name, SceneKind& kind);

struct BenchCamera {
    glm::vec3 eye{0.0f};
    glm::mat4 viewProj{1.0f};
    // Pixels per unit of size at unit distance, for the plants' levels of detail
    // (engine/scene/levels_of_detail.hpp); 0: no levels chosen, every plant at full detail.
    float focalPixels = 0.0f;
    // The crossfade band of the levels of detail (LodView::crossfade); 0: none.
    float crossfade = 0.0f;
};

// The dolly (forest): the still view moved back along its ground direction by kDollyLength
// metres, then forward toward the trees kDollyStep metres a frame — a fixed step, as a
// fixed time step at a fixed speed (60 m/s at 60 Hz) — so every tree and bush crosses its
// level-of-detail thresholds on the way ([Hathaway 2010] §3.1: the racer's view).
inline constexpr float kDollyLength = 116.0f;
inline constexpr float kDollyStep = 1.0f;
inline constexpr int kDollyFrames = int(kDollyLength / kDollyStep) + 1;
// The car's step: 0.25 m a frame, 15 m/s at the racer's 60 Hz.
inline constexpr float kCarStep = 0.25f;

class BenchScene {
public:
    // Throws engine::Error when a content file is missing or bad.
    BenchScene(engine::render::Backend& backend, SceneKind kind, const std::filesystem::path& contentDir);
    // The `layers` scene: `cardLayers` (>= 1) leaf cards, each covering the whole view.
    BenchScene(engine::render::Backend& backend, int cardLayers, const std::filesystem::path& contentDir);
    ~BenchScene();
    BenchScene(const BenchScene&) = delete;
    BenchScene& operator=(const BenchScene&) = delete;

    // From now on the trees and bushes draw their levels of detail (ssam-bench --lod on),
    // chosen for frames `viewportHeight` pixels tall, crossfaded across `crossfade` of each
    // threshold (LodView::crossfade; 0: none). Throws engine::Error when the content's levels
    // are missing or bad.
    void useLevelsOfDetail(int viewportHeight, float crossfade = 0.0f);

    SceneKind kind() const { return kind_; }
    engine::ecs::Registry& registry() { return registry_; }
    const engine::scene::MeshLibrary& library() const { return library_; }

    // The still view every technique is timed and judged on.
    BenchCamera camera(float aspect) const { return view(aspect, 0.0f); }
    // Whether the scene has a sideways pan for the flicker measure (tree and forest: the
    // slow side-to-side move where alpha testing sparkles, [Hathaway 2010] §3.4).
    bool hasPan() const { return panStep_ > 0.0f; }
    // Frame `frame` of the pan: the still view moved `frame` steps sideways (eye and target
    // together, so the view direction stays the same: a pure translation).
    BenchCamera panCamera(float aspect, int frame) const { return view(aspect, panStep_ * float(frame)); }

    // Whether the scene has the dolly (the forest: trees from near to far along the way).
    bool hasDolly() const { return kind_ == SceneKind::Forest; }
    // Whether the scene has the car (the forest): the racer's car crossing the still view in
    // front of the trees, kCarStep metres a frame.
    bool hasCar() const { return kind_ == SceneKind::Forest; }
    // Adds the car (content/models/car.glb), marked MovesRigidly (engine/scene rigid_motion.hpp)
    // so a technique that reads motion vectors gets its motion; placeCar() moves it. Throws
    // engine::Error when the model is missing or bad, or the scene has no car.
    engine::ecs::Entity addCar();
    // The car at frame `frame` of its crossing: on the ground 6 m in front of the still view's
    // eye, driving from left to right across it.
    void placeCar(engine::ecs::Entity car, int frame);
    // Frame `frame` (0 .. kDollyFrames - 1) of the dolly; the last is the still view.
    BenchCamera dollyCamera(float aspect, int frame) const;

private:
    BenchCamera view(float aspect, float sideways, float back = 0.0f) const;

    SceneKind kind_;
    engine::ecs::Registry registry_;
    engine::scene::MeshLibrary library_;
    engine::render::TextureHandle groundTexture_;  // not owned by the library: released here
    glm::vec3 eye_{0.0f}, target_{0.0f, 0.0f, 1.0f};
    float panStep_ = 0.0f;  // metres per pan frame
    std::filesystem::path contentDir_;
    std::vector<std::pair<engine::scene::ModelId, std::string>> plants_;  // each plant model and its file
    int lodViewportHeight_ = 0;                                           // 0: levels of detail off
    float lodCrossfade_ = 0.0f;
};

}  // namespace bench
