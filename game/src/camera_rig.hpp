#pragma once
// The demo's cameras: chase (behind the car), pan (the slow side-to-side pre-race move
// where alpha testing sparkles, seeds/000 §3.4) and free (fly around; a fixed overview
// when headless) and sky (straight up from above the start line: nothing but the sky, the
// no-foliage case the capture tests need). Projection: reverse-Z, 0.1 m to 30 km (seeds/000 §3.1).
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

struct FreeCamera {
    glm::vec3 position{0.0f, 60.0f, -330.0f};
    float yaw = 0.0f;     // radians, 0 looks along +z
    float pitch = -0.12f;
};

inline constexpr float kNearPlane = 0.1f;
inline constexpr float kFarPlane = 30000.0f;

CameraView cameraView(CameraMode mode, RacingScene& scene, float time, float aspect, const FreeCamera& free);

}  // namespace racer
