// SPDX-License-Identifier: MIT
#include "camera_rig.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/core/usage_error.hpp"
#include "engine/render/projection.hpp"
#include "engine/scene/transform.hpp"

namespace racer {

glm::vec3 viewDirection(const FreeCamera& camera) {
    return {std::sin(camera.yaw) * std::cos(camera.pitch), std::sin(camera.pitch),
            std::cos(camera.yaw) * std::cos(camera.pitch)};
}

FreeCamera flyStep(const FreeCamera& camera, const FlyControls& controls, float dt, float speed) {
    constexpr float kPi = glm::pi<float>();
    FreeCamera next = camera;
    next.yaw += controls.turn.x * kFlyTurnRate * dt - controls.look.x * kFlyLookPerPixel;
    next.yaw -= 2.0f * kPi * std::floor((next.yaw + kPi) / (2.0f * kPi));  // into [-pi, pi)
    next.pitch += controls.turn.y * kFlyTurnRate * dt - controls.look.y * kFlyLookPerPixel;
    next.pitch = std::clamp(next.pitch, -kFlyMaxPitch, kFlyMaxPitch);

    // Along the turned view: forward is the full view direction (pitch included), right is
    // horizontal (as glm::lookAt's side vector), up is the world's.
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const glm::vec3 forward = viewDirection(next);
    const glm::vec3 right(-std::cos(next.yaw), 0.0f, std::sin(next.yaw));
    const glm::vec3 direction = controls.move.x * right + controls.move.y * up + controls.move.z * forward;
    const float length = glm::length(direction);
    if (length > 0.0f) {
        const float metres = speed * (controls.fast ? kFlyFastFactor : 1.0f) * dt;
        next.position += direction / length * metres;
    }
    return next;
}

CameraView cameraView(CameraMode mode, RacingScene& scene, float time, float aspect, const FreeCamera& free) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    glm::vec3 eye, target;
    switch (mode) {
        case CameraMode::Chase: {
            const Car& car = scene.registry().get<Car>(scene.car());
            const glm::vec3 p = car.position, f = car.forward;  // the track's, or the player's car's
            // High enough that the line of sight to the car passes over the dust its wheels
            // throw up behind it (modules/particles), low enough to look down the forest road.
            eye = p - f * 9.5f + up * 5.8f;
            target = p + f * 14.0f + up * 0.5f;
            break;
        }
        case CameraMode::Pan: {
            // Grid-side at the start line, drifting slowly along the track and back.
            const Track& track = scene.track();
            const glm::vec3 p = track.position(0.0f), f = track.forward(0.0f);
            const glm::vec3 side = glm::normalize(glm::cross(f, up));
            const glm::vec3 drift = f * (9.0f * std::sin(time * 0.25f));
            eye = p - side * 3.0f + up * 2.5f + drift;
            target = p + side * 30.0f + up * 5.0f + drift;
            break;
        }
        case CameraMode::Sky: {
            // 150 m above the start line, looking 70 degrees up: with a 60 degree field of
            // view the lowest ray still climbs 40 degrees, so no tree, terrain or pool of the
            // scene (all below the eye) can be in view; only the clear colour remains.
            const glm::vec3 p = scene.track().position(0.0f), f = scene.track().forward(0.0f);
            eye = p + up * 150.0f;
            target = eye + f * std::cos(glm::radians(70.0f)) + up * std::sin(glm::radians(70.0f));
            break;
        }
        case CameraMode::Free: {
            eye = free.position;
            target = eye + viewDirection(free);
            break;
        }
    }
    CameraView v;
    v.eye = eye;
    v.view = glm::lookAt(eye, target, up);
    v.projection = engine::render::perspectiveReverseZ(glm::radians(60.0f), aspect, kNearPlane, kFarPlane);
    v.viewProj = v.projection * v.view;
    return v;
}

CameraMode parseCamera(const std::string& name) {
    if (name == "chase") return CameraMode::Chase;
    if (name == "pan") return CameraMode::Pan;
    if (name == "free") return CameraMode::Free;
    if (name == "sky") return CameraMode::Sky;
    throw engine::UsageError("--camera '" + name + "': expected chase, pan, free or sky");
}

const char* cameraName(CameraMode mode) {
    switch (mode) {
        case CameraMode::Chase: return "chase";
        case CameraMode::Pan: return "pan";
        case CameraMode::Free: return "free";
        case CameraMode::Sky: return "sky";
    }
    return "?";
}

CameraMode nextCamera(CameraMode mode) {
    switch (mode) {
        case CameraMode::Chase: return CameraMode::Pan;
        case CameraMode::Pan: return CameraMode::Free;
        default: return CameraMode::Chase;
    }
}

}  // namespace racer
