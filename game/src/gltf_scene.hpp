// SPDX-License-Identifier: MIT
#pragma once
// `racer --scene FILE.gltf|FILE.glb`: any glTF 2.0 file in place of the racing scene. The
// file's scene becomes one entity of the ECS (node transforms are baked into the mesh
// parts by the MeshLibrary), seen through the file's camera or, when it has none, through
// an automatic camera that frames the scene's bounds from the front.
//
// Alpha follows glTF 2.0 §3.9.4: OPAQUE ignores alpha entirely (the MeshLibrary uploads
// their textures with alpha 1), MASK is the foliage the chosen
// technique draws, BLEND is straight-alpha "over" drawn after both, back to front per
// primitive (extractDrawLists).
#include <filesystem>
#include <string>

#include "camera_rig.hpp"
#include "engine/assets/gltf.hpp"
#include "engine/core/ecs/registry.hpp"
#include "engine/scene/mesh_library.hpp"

namespace racer {

struct GltfSceneOptions {
    std::filesystem::path file;
    int sceneIndex = -1;   // -1: the file's default scene (scene 0 when it names none)
    int cameraIndex = -1;  // -1: the first camera a node of the scene carries; none: automatic
};

// The automatic camera: 45° vertical field of view, on the +Z side of the bounds looking
// along -Z (glTF's "front"), as close as it can be while every corner of the bounding box
// stays inside the frame with kAutoCameraMargin to spare: the box's half extent times
// (1 + margin) fits the half field of view, so the scene fills at most 1/1.1 ≈ 91% of the
// frame's width or height and touches that limit in at least one of them.
inline constexpr float kAutoCameraFovY = 0.78539816f;
inline constexpr float kAutoCameraMargin = 0.1f;

// No glTF core light or background exists (KHR_lights_punctual is not read): the scene is
// lit by FrameRenderer's default sun over this neutral 18% grey (linear), a known colour
// for the capture tests' "over" formula.
inline const glm::vec4 kNeutralBackground{0.18f, 0.18f, 0.18f, 1.0f};

// What a view needs besides the matrices: the planes (layer pictures linearise depth).
struct SceneCamera {
    CameraView view;
    float nearPlane = kNearPlane;
    float farPlane = kFarPlane;  // an infinite perspective projection: 1e6 * nearPlane (for depth pictures)
    std::string description;     // e.g. "cameras[1] 'Overview' on nodes[4]", "automatic"
};

// A file camera seen from `nodeWorld`, projected reverse-Z ([Hathaway 2010] §3.1) for the
// viewport's aspect: glTF leaves aspectRatio mismatches to the implementation, and keeping
// yfov (or ymag) with the viewport's aspect never stretches the image.
SceneCamera fileCamera(const engine::assets::Camera& camera, const glm::mat4& nodeWorld, float aspect);
// The automatic camera for world-space bounds (an empty scene: a unit box at the origin).
SceneCamera framingCamera(const engine::assets::Bounds& bounds, float aspect);

class GltfScene {
public:
    // Throws engine::Error naming the file and the field for a bad file, and the valid
    // range for a bad scene or camera index.
    GltfScene(engine::render::Backend& backend, const GltfSceneOptions& options);

    engine::ecs::Registry& registry() { return registry_; }
    engine::scene::MeshLibrary& library() { return library_; }
    const engine::assets::LoadedModel& model() const { return model_; }

    SceneCamera camera(float aspect) const;

private:
    engine::assets::LoadedModel model_;
    engine::ecs::Registry registry_;
    engine::scene::MeshLibrary library_;
    int cameraNode_ = -1;  // -1: the automatic camera
};

}  // namespace racer
