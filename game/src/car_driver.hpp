// SPDX-License-Identifier: MIT
#pragma once
// The player's car (racer's window, chase camera): a kinematic bicycle model on a height
// field. Throttle accelerates against rolling resistance and air drag, the brake stops the
// car and then reverses it, steering turns the heading at speed * tan(wheel angle) /
// wheelbase with the wheel angle narrowing as speed grows (so a full lock at 40 m/s does not
// spin the car), and the car sits on the ground under it, pitched along the slope between
// its axles. No slip, no suspension, no collisions with trunks: enough to drive through the
// bushes and watch them bend (modules/wind pushes foliage out of the car's Collider).
// A pure function of its inputs, so a run with --fixed-dt drives the same path every time.
#include <functional>

#include <glm/glm.hpp>

namespace racer {

// One frame's controls, each in [-1, 1] (window_keys.hpp maps keys to them).
struct DriveControls {
    float throttle = 0.0f;  // 1: accelerate; -1: brake, then reverse once stopped
    float steer = 0.0f;     // 1: full left, -1: full right
    bool operator==(const DriveControls&) const = default;
};

// Where the car is: position on the ground, heading in radians about +y (0 drives along +z,
// positive turns left, towards +x: the free camera's yaw), speed in m/s along the heading
// (negative reversing), pitch in radians (positive: nose up).
struct CarMotion {
    glm::vec3 position{0.0f};
    float heading = 0.0f;
    float speed = 0.0f;
    float pitch = 0.0f;
};

struct CarPhysics {
    float acceleration = 10.0f;  // m/s^2 at full throttle
    float braking = 22.0f;       // m/s^2 at full brake
    float reverseAcceleration = 4.0f;
    float maxSpeed = 48.0f;           // m/s
    float maxReverse = 8.0f;          // m/s
    float rolling = 0.6f;             // m/s^2 of rolling resistance (stops a coasting car)
    float drag = 0.004f;              // 1/m: air drag, drag * speed^2 in m/s^2
    float maxWheelAngle = 0.6f;       // radians, at walking pace
    float steerFalloffSpeed = 12.0f;  // m/s: the wheel angle is max / (1 + (speed / this)^2)
    float wheelbase = 2.6f;           // m
};

// The ground's height (world y) under a point (x, z).
using GroundHeight = std::function<float(float x, float z)>;

// The unit forward direction of a heading (horizontal).
glm::vec3 headingDirection(float heading);

// The wheel angle (radians, positive left) that full `steer` gives at `speed`.
float wheelAngle(float steer, float speed, const CarPhysics& physics = {});

// The motion after `dt` seconds (dt >= 0; 0 only re-seats the car on the ground). Controls
// outside [-1, 1] are clamped and non-finite ones read as 0. The heading wraps into [-pi, pi).
CarMotion driveStep(const CarMotion& car, const DriveControls& controls, float dt, const GroundHeight& ground,
                    const CarPhysics& physics = {});

}  // namespace racer
