// SPDX-License-Identifier: MIT
#include "gltf_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/render/projection.hpp"
#include "engine/scene/components.hpp"

namespace racer {

using namespace engine;

namespace {

// Reverse-Z (depth 1 at znear, 0 at zfar, clear 0, CompareFunc::Greater): the limit of
// perspectiveReverseZ as far -> infinity is depth = znear / distance (glTF 2.0 §3.10.3
// allows an infinite zfar).
glm::mat4 infinitePerspectiveReverseZ(float fovY, float aspect, float near) {
    const float f = 1.0f / std::tan(fovY * 0.5f);
    glm::mat4 m(0.0f);
    m[0][0] = f / aspect;
    m[1][1] = f;
    m[2][3] = -1.0f;
    m[3][2] = near;
    return m;
}

// Orthographic reverse-Z: depth = (far - distance) / (far - near), 1 at near, 0 at far.
glm::mat4 orthographicReverseZ(float halfWidth, float halfHeight, float near, float far) {
    glm::mat4 m(0.0f);
    m[0][0] = 1.0f / halfWidth;
    m[1][1] = 1.0f / halfHeight;
    m[2][2] = 1.0f / (far - near);
    m[3][2] = far / (far - near);
    m[3][3] = 1.0f;
    return m;
}

SceneCamera finish(SceneCamera c, const glm::mat4& cameraWorld, const glm::mat4& projection) {
    c.view.eye = glm::vec3(cameraWorld[3]);
    c.view.view = glm::inverse(cameraWorld);
    c.view.projection = projection;
    c.view.viewProj = projection * c.view.view;
    return c;
}

std::string quoted(const std::string& name) { return name.empty() ? "" : " '" + name + "'"; }

}  // namespace

SceneCamera fileCamera(const assets::Camera& camera, const glm::mat4& nodeWorld, float aspect) {
    // glTF 2.0 §3.10.1: a camera looks along its node's -Z with +Y up; the node's scale
    // does not apply to the view, so the axes are normalised.
    glm::mat4 world(1.0f);
    for (int axis = 0; axis < 3; ++axis) {
        const glm::vec3 column(nodeWorld[axis]);
        const float length = glm::length(column);
        if (!(length > 0.0f)) throw Error("the camera's node transform is degenerate (zero scale)");
        world[axis] = glm::vec4(column / length, 0.0f);
    }
    world[3] = glm::vec4(glm::vec3(nodeWorld[3]), 1.0f);
    SceneCamera c;
    c.nearPlane = camera.znear;
    // An infinite projection has no far plane; the depth pictures (layer_pictures.cpp) show
    // distances up to a million times znear instead.
    c.farPlane = std::isinf(camera.zfar) ? camera.znear * 1e6f : camera.zfar;
    if (camera.type == assets::Camera::Type::Perspective) {
        const glm::mat4 projection = std::isinf(camera.zfar)
                                         ? infinitePerspectiveReverseZ(camera.yfov, aspect, camera.znear)
                                         : render::perspectiveReverseZ(camera.yfov, aspect, camera.znear, camera.zfar);
        return finish(c, world, projection);
    }
    const float halfHeight = std::abs(camera.ymag);
    return finish(c, world, orthographicReverseZ(halfHeight * aspect, halfHeight, camera.znear, camera.zfar));
}

SceneCamera framingCamera(const assets::Bounds& sceneBounds, float aspect) {
    assets::Bounds bounds = sceneBounds;
    if (bounds.empty()) {
        bounds.add(glm::vec3(-0.5f));
        bounds.add(glm::vec3(0.5f));
    }
    const glm::vec3 centre = (bounds.min + bounds.max) * 0.5f;
    const glm::vec3 half = (bounds.max - bounds.min) * 0.5f;
    const float size = std::max(glm::length(half), 1e-3f);
    const float tanY = std::tan(kAutoCameraFovY * 0.5f) / (1.0f + kAutoCameraMargin);
    const float tanX = tanY * aspect;
    // The camera sits at centre + (0, 0, d). A corner at (x, y, z) relative to the centre is
    // d - z in front of it and must satisfy |x| <= tanX (d - z) and |y| <= tanY (d - z); the
    // nearest corners (z = +half.z) decide, so d = half.z + max(half.x / tanX, half.y / tanY).
    float distance = half.z + std::max(half.x / tanX, half.y / tanY);
    distance = std::max(distance, half.z + size * 1e-3f);  // a point or a line along Z: still in front
    SceneCamera c;
    c.description = "automatic (45° fov, 10% margin)";
    c.nearPlane = std::max((distance - half.z) * 0.5f, size * 1e-4f);
    c.farPlane = (distance + half.z) * 2.0f + size;
    glm::mat4 world(1.0f);
    world[3] = glm::vec4(centre + glm::vec3(0.0f, 0.0f, distance), 1.0f);
    return finish(c, world, render::perspectiveReverseZ(kAutoCameraFovY, aspect, c.nearPlane, c.farPlane));
}

namespace {

assets::LoadedModel load(const GltfSceneOptions& options) {
    assets::LoadOptions load;
    load.scene = options.sceneIndex;
    return assets::loadGltf(options.file, load);
}

}  // namespace

GltfScene::GltfScene(render::Backend& backend, const GltfSceneOptions& options)
    : model_(load(options)), library_(backend) {
    const std::string file = options.file.filename().string();
    const std::size_t cameraCount = model_.cameras.size();
    if (options.cameraIndex >= 0 && static_cast<std::size_t>(options.cameraIndex) >= cameraCount)
        throw Error(file + ": --camera-index " + std::to_string(options.cameraIndex) + " is out of range: " +
                    (cameraCount == 0 ? std::string("the file has no cameras")
                                      : "the file has " + std::to_string(cameraCount) + " cameras (valid: 0.." +
                                            std::to_string(cameraCount - 1) + ")"));
    // The requested camera, or the lowest-numbered one a node of the scene carries.
    for (int n : model_.sceneNodes) {
        const int camera = model_.nodes[static_cast<std::size_t>(n)].camera;
        if (camera < 0 || (options.cameraIndex >= 0 && camera != options.cameraIndex)) continue;
        if (cameraNode_ < 0 || camera < model_.nodes[static_cast<std::size_t>(cameraNode_)].camera) cameraNode_ = n;
    }
    if (options.cameraIndex >= 0 && cameraNode_ < 0)
        throw Error(file + ": --camera-index " + std::to_string(options.cameraIndex) + ": no node of scene " +
                    std::to_string(model_.scene) + " carries cameras[" + std::to_string(options.cameraIndex) + "]");

    const ecs::Entity entity = registry_.create();
    registry_.add<scene::Transform>(entity, scene::Transform{});
    registry_.add<scene::Renderable>(entity, scene::Renderable{library_.add(model_)});
}

SceneCamera GltfScene::camera(float aspect) const {
    if (cameraNode_ < 0) return framingCamera(model_.bounds, aspect);
    const assets::Node& node = model_.nodes[static_cast<std::size_t>(cameraNode_)];
    const assets::Camera& camera = model_.cameras[static_cast<std::size_t>(node.camera)];
    SceneCamera c = fileCamera(camera, node.world, aspect);
    c.description = "cameras[" + std::to_string(node.camera) + "]" + quoted(camera.name) + " on nodes[" +
                    std::to_string(cameraNode_) + "]" + quoted(node.name);
    return c;
}

}  // namespace racer
