// SPDX-License-Identifier: MIT
// The player's car (game/src/car_driver.hpp): speed, steering, staying on the ground, and
// the same path for the same inputs at a fixed step.
#include <cmath>
#include <vector>
#include <gtest/gtest.h>

#include "car_driver.hpp"

namespace racer {
namespace {

const GroundHeight kFlat = [](float, float) { return 0.0f; };
// A slope rising 1 m per 10 m along +z, with a bump across x.
const GroundHeight kSlope = [](float x, float z) { return 0.1f * z + 0.5f * std::sin(0.3f * x); };

CarMotion drive(CarMotion car, DriveControls controls, int frames, float dt = 0.1f,
                const GroundHeight& ground = kFlat) {
    for (int i = 0; i < frames; ++i) car = driveStep(car, controls, dt, ground);
    return car;
}

TEST(CarDriver, ThrottleAcceleratesUpToTheTopSpeed) {
    const CarPhysics p;
    const CarMotion oneSecond = drive({}, {1.0f, 0.0f}, 10);
    // 10 m/s^2 less rolling resistance and drag: a little under 10 m/s after a second.
    EXPECT_GT(oneSecond.speed, 9.0f);
    EXPECT_LT(oneSecond.speed, p.acceleration);
    EXPECT_NEAR(oneSecond.position.z, 4.7f, 0.3f);  // about a t^2 / 2
    const CarMotion flatOut = drive({}, {1.0f, 0.0f}, 600);
    EXPECT_LE(flatOut.speed, p.maxSpeed);
    EXPECT_GT(flatOut.speed, 0.9f * p.maxSpeed);
}

TEST(CarDriver, CoastingStopsWithoutRollingBack) {
    const CarMotion stopped = drive({{}, 0.0f, 20.0f}, {}, 2000);
    EXPECT_EQ(stopped.speed, 0.0f);
    const CarMotion slower = drive({{}, 0.0f, 20.0f}, {}, 10);
    EXPECT_LT(slower.speed, 20.0f);
    EXPECT_GT(slower.speed, 17.0f);
}

TEST(CarDriver, BrakeStopsThenReverses) {
    // 20 m/s under 22 m/s^2 of braking (and the resistances) stops within a second...
    const CarMotion braked = drive({{}, 0.0f, 20.0f}, {-1.0f, 0.0f}, 9);
    EXPECT_EQ(braked.speed, 0.0f);
    // ... then the same key reverses, no faster than the reverse limit.
    const CarMotion reversing = drive(braked, {-1.0f, 0.0f}, 10);
    EXPECT_LT(reversing.speed, 0.0f);
    const CarMotion reversed = drive(braked, {-1.0f, 0.0f}, 200);
    EXPECT_EQ(reversed.speed, -CarPhysics{}.maxReverse);
    EXPECT_LT(reversed.position.z, braked.position.z);
    // The throttle brakes a reversing car to a stop first.
    EXPECT_EQ(driveStep(reversing, {1.0f, 0.0f}, 0.5f, kFlat).speed, 0.0f);
}

TEST(CarDriver, SteeringTurnsLeftAndRightOnACircleOfTheBicycleRadius) {
    const CarPhysics p;
    const float speed = 10.0f;
    const CarMotion left = drive({{}, 0.0f, speed}, {0.0f, 1.0f}, 1, 0.1f);
    const CarMotion right = drive({{}, 0.0f, speed}, {0.0f, -1.0f}, 1, 0.1f);
    EXPECT_GT(left.heading, 0.0f);  // towards +x
    EXPECT_GT(left.position.x, 0.0f);
    EXPECT_FLOAT_EQ(right.heading, -left.heading);
    // Holding speed (throttle balancing the resistances is not needed: compare the yaw rate).
    const float yawRate = left.heading / 0.1f;
    // The mean speed over the step is a little under 10 m/s (rolling resistance).
    const float mean = 0.5f * (speed + left.speed);
    EXPECT_NEAR(yawRate, mean * std::tan(wheelAngle(1.0f, mean)) / p.wheelbase, 1e-4f);
    // The wheel angle narrows with speed: a full lock turns the car less sharply at 40 m/s.
    EXPECT_LT(wheelAngle(1.0f, 40.0f), 0.2f * wheelAngle(1.0f, 0.0f));
    // A car at rest does not turn.
    EXPECT_EQ(drive({}, {0.0f, 1.0f}, 5).heading, 0.0f);
    // The heading wraps: driving in circles for a while keeps it in [-pi, pi).
    const CarMotion circles = drive({{}, 0.0f, speed}, {0.2f, 1.0f}, 2000);
    EXPECT_GE(circles.heading, -3.14159275f);
    EXPECT_LT(circles.heading, 3.14159275f);
}

TEST(CarDriver, StaysOnTheGroundPitchedAlongTheSlope) {
    CarMotion car{{3.0f, 40.0f, 0.0f}, 0.0f, 15.0f};  // starts in the air: set down on the first step
    for (int i = 0; i < 50; ++i) {
        car = driveStep(car, {1.0f, i < 25 ? 0.5f : -0.5f}, 0.05f, kSlope);
        EXPECT_FLOAT_EQ(car.position.y, kSlope(car.position.x, car.position.z)) << "frame " << i;
    }
    // Driving straight up the slope: nose up by atan(0.1).
    const CarMotion uphill =
        driveStep({{0.0f, 0.0f, 0.0f}, 0.0f, 10.0f}, {}, 0.1f, [](float, float z) { return 0.1f * z; });
    EXPECT_NEAR(uphill.pitch, std::atan(0.1f), 1e-5f);
    const CarMotion downhill =
        driveStep({{0.0f, 0.0f, 0.0f}, 3.14159265f, 10.0f}, {}, 0.1f, [](float, float z) { return 0.1f * z; });
    EXPECT_NEAR(downhill.pitch, -std::atan(0.1f), 1e-5f);
    // dt 0 only seats the car.
    const CarMotion seated = driveStep({{1.0f, 9.0f, 2.0f}, 0.3f, 5.0f}, {1.0f, 1.0f}, 0.0f, kSlope);
    EXPECT_EQ(seated.speed, 5.0f);
    EXPECT_EQ(seated.heading, 0.3f);
    EXPECT_FLOAT_EQ(seated.position.y, kSlope(1.0f, 2.0f));
}

TEST(CarDriver, SameInputsAtAFixedStepDriveTheSamePath) {
    auto lap = [] {
        std::vector<CarMotion> path;
        CarMotion car{{5.0f, 0.0f, -2.0f}, 0.4f, 12.0f};
        for (int i = 0; i < 300; ++i) {
            const DriveControls c{i % 50 < 30 ? 1.0f : -0.5f, std::sin(float(i) * 0.05f)};
            car = driveStep(car, c, 1.0f / 30.0f, kSlope);
            path.push_back(car);
        }
        return path;
    };
    const auto a = lap(), b = lap();
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].position, b[i].position);
        EXPECT_EQ(a[i].heading, b[i].heading);
        EXPECT_EQ(a[i].speed, b[i].speed);
    }
    EXPECT_GT(glm::length(a.back().position - a.front().position), 10.0f);  // it went somewhere
}

TEST(CarDriver, OutOfRangeAndNonFiniteControlsAreTamed) {
    const CarMotion start{{}, 0.0f, 10.0f};
    const CarMotion huge = driveStep(start, {50.0f, -50.0f}, 0.1f, kFlat);
    const CarMotion unit = driveStep(start, {1.0f, -1.0f}, 0.1f, kFlat);
    EXPECT_EQ(huge.speed, unit.speed);
    EXPECT_EQ(huge.heading, unit.heading);
    const CarMotion nan = driveStep(start, {std::nanf(""), std::nanf("")}, 0.1f, kFlat);
    const CarMotion none = driveStep(start, {}, 0.1f, kFlat);
    EXPECT_EQ(nan.speed, none.speed);
    EXPECT_EQ(nan.heading, none.heading);
}

}  // namespace
}  // namespace racer
