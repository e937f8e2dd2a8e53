// SPDX-License-Identifier: MIT
#pragma once
// The demo's cameras: chase (behind the car), pan (the slow side-to-side pre-race move
// where alpha testing sparkles, [Hathaway 2010] §3.4), free (a free-fly camera: it starts at an
// overview of the track, which is all a headless run sees; the window flies it, keys in
// window_keys.hpp) and sky (straight up from above the start line: nothing but the sky, the
// no-foliage case the capture tests need). Projection: reverse-Z, 0.1 m to 30 km ([Hathaway 2010] §3.1).
#include <string>

#include <glm/glm.hpp>

#include "racing_scene.hpp"

namespace racer {

enum class CameraMode { Chase, Pan, Free, Sky };

struct CameraView {
    glm::vec3 eye{0.0f};
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProj{1.0f};
};

// The free camera's pose; the default is the overview every run starts from.
struct FreeCamera {
    glm::vec3 position{0.0f, 60.0f, -330.0f};
    float yaw = 0.0f;      // radians, 0 looks along +z, positive turns left (towards +x)
    float pitch = -0.12f;  // radians, positive looks up
};

// One frame's fly controls (window_keys.hpp maps keys to them). Each axis is -1, 0 or 1:
// move.x strafes right, move.y climbs (world up), move.z goes forward along the view
// direction; turn.x turns left, turn.y looks up. look: mouse motion in pixels (+x right,
// +y down, GLFW's screen convention) while the right button is held.
struct FlyControls {
    glm::vec3 move{0.0f};
    glm::vec2 turn{0.0f};
    glm::vec2 look{0.0f};
    bool fast = false;
};

inline constexpr float kFlySpeed = 20.0f;                   // metres per second
inline constexpr float kFlyFastFactor = 5.0f;               // with Shift
inline constexpr float kFlyTurnRate = 1.5f;                 // radians per second (arrow keys)
inline constexpr float kFlyLookPerPixel = 0.0025f;          // radians per pixel of mouse motion
inline constexpr float kFlyMaxPitch = glm::radians(89.0f);  // never straight up/down: lookAt's up would be parallel

// The unit view direction of a pose.
glm::vec3 viewDirection(const FreeCamera& camera);

// The pose after one frame of `dt` seconds: movement and arrow-key turns scale with dt (so a
// run with --fixed-dt flies the same path every time), mouse look with the pixels moved. A
// diagonal move is as fast as a straight one. Yaw wraps into [-pi, pi), pitch is clamped to
// +-kFlyMaxPitch.
FreeCamera flyStep(const FreeCamera& camera, const FlyControls& controls, float dt, float speed = kFlySpeed);

inline constexpr float kNearPlane = 0.1f;
inline constexpr float kFarPlane = 30000.0f;

CameraView cameraView(CameraMode mode, RacingScene& scene, float time, float aspect, const FreeCamera& free);

// "chase", "pan", "free", "sky"; throws engine::UsageError quoting --camera otherwise.
CameraMode parseCamera(const std::string& name);
const char* cameraName(CameraMode mode);
// The C key's order: chase, pan, free, then chase again (sky only by flag).
CameraMode nextCamera(CameraMode mode);

}  // namespace racer
