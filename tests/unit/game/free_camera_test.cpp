// SPDX-License-Identifier: MIT
// racer's free-fly camera (game/src/camera_rig.hpp): flyStep's movement and rotation, without
// a window or a scene.
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include "camera_rig.hpp"

namespace racer {
namespace {

constexpr float kTolerance = 1e-4f;

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance = kTolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

FlyControls moving(float x, float y, float z) {
    FlyControls c;
    c.move = {x, y, z};
    return c;
}

TEST(FreeCamera, StartsAtTheHeadlessOverview) {
    // The pose headless `--camera free` captures render; the window starts there too.
    const FreeCamera c;
    expectNear(c.position, {0.0f, 60.0f, -330.0f}, 0.0f);
    EXPECT_EQ(c.yaw, 0.0f);
    EXPECT_EQ(c.pitch, -0.12f);
}

TEST(FreeCamera, ViewDirectionIsUnitAndFollowsYawAndPitch) {
    FreeCamera c;
    c.pitch = 0.0f;
    expectNear(viewDirection(c), {0.0f, 0.0f, 1.0f});
    c.yaw = glm::half_pi<float>();  // positive yaw turns left: towards +x
    expectNear(viewDirection(c), {1.0f, 0.0f, 0.0f});
    c.pitch = 0.7f;
    EXPECT_NEAR(glm::length(viewDirection(c)), 1.0f, kTolerance);
    EXPECT_NEAR(viewDirection(c).y, std::sin(0.7f), kTolerance);
}

TEST(FreeCamera, ForwardForOneSecondMovesSpeedMetresAlongTheView) {
    FreeCamera start;
    start.yaw = 0.8f;
    start.pitch = -0.3f;
    for (const float speed : {1.0f, 7.5f, kFlySpeed}) {
        const FreeCamera end = flyStep(start, moving(0, 0, 1), 1.0f, speed);
        expectNear(end.position - start.position, viewDirection(start) * speed);
        EXPECT_EQ(end.yaw, start.yaw);
        EXPECT_EQ(end.pitch, start.pitch);
        // Back is the opposite way, and ten 0.1 s steps go as far as one 1 s step.
        const FreeCamera back = flyStep(start, moving(0, 0, -1), 1.0f, speed);
        expectNear(back.position - start.position, -viewDirection(start) * speed);
        FreeCamera stepped = start;
        for (int i = 0; i < 10; ++i) stepped = flyStep(stepped, moving(0, 0, 1), 0.1f, speed);
        expectNear(stepped.position, end.position, 1e-3f);
    }
}

TEST(FreeCamera, StrafeIsHorizontalAndRightOnScreen) {
    FreeCamera start;  // yaw 0 looks along +z: the screen's right is -x (right-handed, y up)
    const glm::vec3 moved = flyStep(start, moving(1, 0, 0), 2.0f, 3.0f).position - start.position;
    expectNear(moved, {-6.0f, 0.0f, 0.0f});
    // glm::lookAt's side vector is the screen's right: strafing must agree with it.
    const glm::vec3 side = glm::normalize(glm::cross(viewDirection(start), glm::vec3(0, 1, 0)));
    expectNear(glm::normalize(moved), side);
}

TEST(FreeCamera, UpIsTheWorldsUpAndDiagonalsAreNotFaster) {
    FreeCamera start;
    start.pitch = 0.5f;
    expectNear(flyStep(start, moving(0, 1, 0), 1.0f, 4.0f).position - start.position, {0.0f, 4.0f, 0.0f});
    expectNear(flyStep(start, moving(0, -1, 0), 1.0f, 4.0f).position - start.position, {0.0f, -4.0f, 0.0f});
    const glm::vec3 diagonal = flyStep(start, moving(1, 1, 1), 1.0f, 4.0f).position - start.position;
    EXPECT_NEAR(glm::length(diagonal), 4.0f, kTolerance);
}

TEST(FreeCamera, ShiftMultipliesTheSpeedAndZeroDtStaysPut) {
    FreeCamera start;
    FlyControls fast = moving(0, 0, 1);
    fast.fast = true;
    EXPECT_NEAR(glm::length(flyStep(start, fast, 0.5f, 10.0f).position - start.position), 0.5f * 10.0f * kFlyFastFactor,
                kTolerance);
    const FreeCamera still = flyStep(start, fast, 0.0f, 10.0f);
    expectNear(still.position, start.position, 0.0f);
    // No controls: the pose is unchanged bit for bit (a headless-equal start stays equal).
    const FreeCamera idle = flyStep(start, FlyControls{}, 0.25f);
    EXPECT_EQ(idle.position, start.position);
    EXPECT_EQ(idle.yaw, start.yaw);
    EXPECT_EQ(idle.pitch, start.pitch);
}

TEST(FreeCamera, ArrowTurnsScaleWithDtAndMouseWithPixels) {
    FreeCamera start;
    FlyControls left;
    left.turn = {1.0f, 0.0f};
    EXPECT_NEAR(flyStep(start, left, 0.5f).yaw, start.yaw + 0.5f * kFlyTurnRate, kTolerance);
    FlyControls up;
    up.turn = {0.0f, 1.0f};
    EXPECT_NEAR(flyStep(start, up, 0.2f).pitch, start.pitch + 0.2f * kFlyTurnRate, kTolerance);
    // Mouse right turns right (yaw down), mouse up (screen y decreasing) looks up; dt plays no part.
    FlyControls mouse;
    mouse.look = {40.0f, -20.0f};
    for (const float dt : {0.0f, 1.0f}) {
        const FreeCamera turned = flyStep(start, mouse, dt);
        EXPECT_NEAR(turned.yaw, start.yaw - 40.0f * kFlyLookPerPixel, kTolerance);
        EXPECT_NEAR(turned.pitch, start.pitch + 20.0f * kFlyLookPerPixel, kTolerance);
    }
}

TEST(FreeCamera, PitchClampsAtEightyNineDegrees) {
    FreeCamera start;
    FlyControls up;
    up.turn = {0.0f, 1.0f};
    const FreeCamera top = flyStep(start, up, 10.0f);
    EXPECT_FLOAT_EQ(top.pitch, glm::radians(89.0f));
    FlyControls down;
    down.look = {0.0f, 1e6f};
    EXPECT_FLOAT_EQ(flyStep(start, down, 0.0f).pitch, -glm::radians(89.0f));
    // At the clamp the view still has a horizontal part, so lookAt's up is never parallel.
    EXPECT_GT(std::cos(top.pitch), 0.017f);
}

TEST(FreeCamera, YawWrapsIntoMinusPiToPi) {
    constexpr float kPi = glm::pi<float>();
    FreeCamera start;
    start.yaw = 3.0f;
    FlyControls left;
    left.turn = {1.0f, 0.0f};
    const FreeCamera wrapped = flyStep(start, left, 1.0f);  // 3 + 1.5 rad = 4.5 - 2 pi
    EXPECT_NEAR(wrapped.yaw, 4.5f - 2.0f * kPi, kTolerance);
    EXPECT_GE(wrapped.yaw, -kPi);
    EXPECT_LT(wrapped.yaw, kPi);
    // Many turns either way stay in range and equal the same angle.
    FreeCamera spun = start;
    FlyControls right;
    right.turn = {-1.0f, 0.0f};
    for (int i = 0; i < 100; ++i) spun = flyStep(spun, right, 0.1f);  // -15 rad
    EXPECT_GE(spun.yaw, -kPi);
    EXPECT_LT(spun.yaw, kPi);
    EXPECT_NEAR(std::remainder(spun.yaw - (3.0f - 15.0f), 2.0f * kPi), 0.0f, 1e-3f);
    // Wrapping keeps the view: the same direction as the unwrapped angle.
    FreeCamera unwrapped = start;
    unwrapped.yaw = 4.5f;
    expectNear(viewDirection(wrapped), viewDirection(unwrapped));
}

}  // namespace
}  // namespace racer
