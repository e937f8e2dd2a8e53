// SPDX-License-Identifier: MIT
#include "car_driver.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace racer {

namespace {

float control(float v) { return std::isfinite(v) ? std::clamp(v, -1.0f, 1.0f) : 0.0f; }

// Speed after dt: throttle pushes (forward brakes a reversing car and the brake a rolling
// one, each stopping it at zero in the frame it gets there; from rest they accelerate and
// reverse), then rolling resistance and air drag pull towards zero but never through it (a
// coasting car stops, it does not roll back).
float nextSpeed(float speed, float throttle, float dt, const CarPhysics& p) {
    float next;
    if (throttle > 0.0f && speed < 0.0f) next = std::min(0.0f, speed + throttle * p.braking * dt);
    else if (throttle < 0.0f && speed > 0.0f) next = std::max(0.0f, speed + throttle * p.braking * dt);
    else next = speed + throttle * (throttle > 0.0f ? p.acceleration : p.reverseAcceleration) * dt;
    const float resist = (p.rolling + p.drag * speed * speed) * dt;
    if (next > 0.0f) next = std::max(0.0f, next - resist);
    else if (next < 0.0f) next = std::min(0.0f, next + resist);
    return std::clamp(next, -p.maxReverse, p.maxSpeed);
}

}  // namespace

glm::vec3 headingDirection(float heading) { return {std::sin(heading), 0.0f, std::cos(heading)}; }

float wheelAngle(float steer, float speed, const CarPhysics& p) {
    const float r = speed / p.steerFalloffSpeed;
    return control(steer) * p.maxWheelAngle / (1.0f + r * r);
}

CarMotion driveStep(const CarMotion& car, const DriveControls& controls, float dt, const GroundHeight& ground,
                    const CarPhysics& p) {
    constexpr float kPi = glm::pi<float>();
    CarMotion next = car;
    if (dt > 0.0f && std::isfinite(dt)) {
        next.speed = nextSpeed(car.speed, control(controls.throttle), dt, p);
        // The rear axle follows the front: yaw rate = v tan(wheel angle) / wheelbase, at the
        // step's mean speed so a car braking to a stop does not turn on the spot.
        const float speed = 0.5f * (car.speed + next.speed);
        next.heading += speed * std::tan(wheelAngle(controls.steer, speed, p)) / p.wheelbase * dt;
        next.heading -= 2.0f * kPi * std::floor((next.heading + kPi) / (2.0f * kPi));
        next.position += headingDirection(next.heading) * (speed * dt);
    }
    // On the ground: the height under the car's centre, pitched along the slope between its axles.
    const glm::vec3 half = headingDirection(next.heading) * (0.5f * p.wheelbase);
    const float front = ground(next.position.x + half.x, next.position.z + half.z);
    const float back = ground(next.position.x - half.x, next.position.z - half.z);
    next.position.y = ground(next.position.x, next.position.z);
    next.pitch = std::atan2(front - back, p.wheelbase);
    return next;
}

}  // namespace racer
