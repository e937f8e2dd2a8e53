// SPDX-License-Identifier: MIT
// racer's window keys (game/src/window_keys.hpp): the key -> action mapping and the test
// window script's parser, without a window.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <initializer_list>
#include <string>
#include <vector>
#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "window_keys.hpp"

namespace racer {
namespace {

TEST(WindowKeys, DigitsSelectTechniquesInTableOrder) {
    for (int i = 0; i < 8; ++i) {
        const KeyAction top = actionForKey(GLFW_KEY_1 + i, false);
        EXPECT_EQ(top.action, WindowAction::SelectTechnique);
        EXPECT_EQ(top.technique, i);
        EXPECT_EQ(actionForKey(GLFW_KEY_KP_1 + i, true).technique, i);
    }
    EXPECT_EQ(actionForKey(GLFW_KEY_9, false).action, WindowAction::None);
    EXPECT_EQ(actionForKey(GLFW_KEY_0, false).action, WindowAction::None);
}

TEST(WindowKeys, LettersAndEscape) {
    EXPECT_EQ(actionForKey(GLFW_KEY_T, false).action, WindowAction::NextTechnique);
    EXPECT_EQ(actionForKey(GLFW_KEY_T, true).action, WindowAction::PreviousTechnique);
    EXPECT_EQ(actionForKey(GLFW_KEY_C, false).action, WindowAction::NextCamera);
    EXPECT_EQ(actionForKey(GLFW_KEY_P, false).action, WindowAction::TogglePause);
    EXPECT_EQ(actionForKey(GLFW_KEY_R, false).action, WindowAction::Autopilot);
    EXPECT_EQ(actionForKey(GLFW_KEY_H, false).action, WindowAction::ToggleHud);
    EXPECT_EQ(actionForKey(GLFW_KEY_V, false).action, WindowAction::ToggleCompare);
    EXPECT_EQ(actionForKey(GLFW_KEY_B, false).action, WindowAction::NextCompared);
    EXPECT_EQ(actionForKey(GLFW_KEY_ESCAPE, false).action, WindowAction::Quit);
    EXPECT_EQ(actionForKey(GLFW_KEY_X, false).action, WindowAction::None);
}

TEST(WindowKeys, EveryMappedKeyIsWatched) {
    for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key) {
        const bool mapped = actionForKey(key, false).action != WindowAction::None;
        const bool watched = std::find(watchedKeys().begin(), watchedKeys().end(), key) != watchedKeys().end();
        EXPECT_EQ(mapped, watched) << "GLFW key " << key;
    }
}

TEST(WindowKeys, DriveKeysAccelerateBrakeAndSteer) {
    auto holding = [](std::initializer_list<int> keys) {
        return driveControls([keys](int key) { return std::find(keys.begin(), keys.end(), key) != keys.end(); });
    };
    EXPECT_FALSE(holding({}).any);
    EXPECT_EQ(holding({}).controls, DriveControls{});
    EXPECT_EQ(holding({GLFW_KEY_W}).controls, (DriveControls{1.0f, 0.0f}));
    EXPECT_EQ(holding({GLFW_KEY_UP, GLFW_KEY_LEFT}).controls, (DriveControls{1.0f, 1.0f}));
    EXPECT_EQ(holding({GLFW_KEY_S, GLFW_KEY_D}).controls, (DriveControls{-1.0f, -1.0f}));
    EXPECT_EQ(holding({GLFW_KEY_DOWN, GLFW_KEY_RIGHT}).controls, (DriveControls{-1.0f, -1.0f}));
    EXPECT_EQ(holding({GLFW_KEY_W, GLFW_KEY_S, GLFW_KEY_A, GLFW_KEY_D}).controls, DriveControls{});  // cancel
    EXPECT_TRUE(holding({GLFW_KEY_W, GLFW_KEY_S}).any);  // still a hand on the wheel
    EXPECT_FALSE(holding({GLFW_KEY_Q, GLFW_KEY_SPACE, GLFW_KEY_R}).any);
    for (int key : driveKeys()) {
        EXPECT_TRUE(holding({key}).any) << key;
        EXPECT_EQ(actionForKey(key, false).action, WindowAction::None) << key;  // driving never switches anything
    }
    EXPECT_EQ(parseWindowScript("3:r").keys[0].key, GLFW_KEY_R);
    EXPECT_EQ(parseWindowScript("3:H").keys[0].key, GLFW_KEY_H);
    EXPECT_EQ(parseWindowScript("3:v,4:B").keys[1].key, GLFW_KEY_B);
}

TEST(WindowKeys, ScriptParsesAndSortsByFrame) {
    const auto keys = parseWindowScript("4:Esc,0:3,2:shift+T,1:c").keys;
    ASSERT_EQ(keys.size(), 4u);
    EXPECT_EQ(keys[0].frame, 0);
    EXPECT_EQ(keys[0].key, GLFW_KEY_3);
    EXPECT_EQ(keys[1].key, GLFW_KEY_C);
    EXPECT_EQ(keys[2].key, GLFW_KEY_T);
    EXPECT_TRUE(keys[2].shift);
    EXPECT_EQ(keys[3].key, GLFW_KEY_ESCAPE);
    const WindowScript none = parseWindowScript("");
    EXPECT_TRUE(none.keys.empty());
    EXPECT_TRUE(none.changes.empty());
}

TEST(WindowKeys, BadScriptEntriesAreNamed) {
    for (const char* bad : {"3",
                            "x:T",
                            "-1:T",
                            "2:Z",
                            "2:9",
                            "1:T,",
                            "5-3:W",
                            "1-:W",
                            "1-x:W",
                            "1+2:W",
                            "1:size=",
                            "1:size=400",
                            "1:size=400x",
                            "1:size=x300",
                            "1:size=0x300",
                            "1:size=400x0",
                            "1:size=40000x300",
                            "1:size=-4x300",
                            "1:size=400x300x2",
                            "1:size=400 x300",
                            "1-3:size=400x300",
                            "1:minimize=",
                            "1:minimize=0",
                            "1:minimize=60001",
                            "1:minimize=2s",
                            "1:maximize=1",
                            "1:=5"}) {
        try {
            parseWindowScript(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const engine::Error& e) {
            EXPECT_NE(std::string(e.what()).find("--script entry"), std::string::npos) << e.what();
        }
    }
}

TEST(WindowKeys, ScriptResizesAndMinimisesTheWindowAtFrames) {
    const WindowScript script = parseWindowScript("6:minimize=250,2:W,3:size=400x300,1:Size=32767X1,6:Esc");
    ASSERT_EQ(script.keys.size(), 2u);
    EXPECT_EQ(script.keys[0].key, GLFW_KEY_W);
    EXPECT_EQ(script.keys[1].key, GLFW_KEY_ESCAPE);
    ASSERT_EQ(script.changes.size(), 3u);
    EXPECT_EQ(script.changes[0].frame, 1);  // sorted by frame; names are case-blind as keys are
    EXPECT_EQ(script.changes[0].width, 32767);
    EXPECT_EQ(script.changes[0].height, 1);
    EXPECT_EQ(script.changes[0].minimizeMs, 0);
    EXPECT_EQ(script.changes[1].frame, 3);
    EXPECT_EQ(script.changes[1].width, 400);
    EXPECT_EQ(script.changes[1].height, 300);
    EXPECT_EQ(script.changes[2].frame, 6);
    EXPECT_EQ(script.changes[2].minimizeMs, 250);
    EXPECT_EQ(script.changes[2].width, 0);
}

TEST(WindowKeys, ScriptHoldsKeysForFrameRanges) {
    const auto keys = parseWindowScript("2-4:W,0:c,6-6:shift+Left,9:Esc").keys;
    ASSERT_EQ(keys.size(), 4u);
    EXPECT_EQ(keys[0].key, GLFW_KEY_C);
    EXPECT_EQ(keys[0].lastFrame, 0);
    EXPECT_EQ(keys[1].key, GLFW_KEY_W);
    EXPECT_EQ(keys[1].frame, 2);
    EXPECT_EQ(keys[1].lastFrame, 4);
    EXPECT_EQ(keys[2].key, GLFW_KEY_LEFT);
    EXPECT_TRUE(keys[2].shift);
    for (int frame = 0; frame < 8; ++frame) {
        EXPECT_EQ(scriptHolds(keys, frame, GLFW_KEY_W), frame >= 2 && frame <= 4) << frame;
        EXPECT_EQ(scriptHolds(keys, frame, GLFW_KEY_LEFT_SHIFT), frame == 6) << frame;
    }
    EXPECT_TRUE(scriptHolds(keys, 0, GLFW_KEY_C));  // a press is held for its own frame
    EXPECT_FALSE(scriptHolds(keys, 1, GLFW_KEY_C));
    for (const char* name : {"W", "a", "S", "d", "Q", "e", "Space", "Ctrl", "Left", "Right", "Up", "Down"})
        EXPECT_NO_THROW(parseWindowScript(std::string("0:") + name)) << name;
}

// A held-key set for flyControls.
auto holding(std::initializer_list<int> keys) {
    return [held = std::vector<int>(keys)](int key) { return std::find(held.begin(), held.end(), key) != held.end(); };
}

TEST(WindowKeys, FlyKeysMapToFreeCameraControls) {
    const FlyControls none = flyControls(holding({}));
    EXPECT_EQ(none.move, glm::vec3(0.0f));
    EXPECT_EQ(none.turn, glm::vec2(0.0f));
    EXPECT_FALSE(none.fast);
    EXPECT_EQ(flyControls(holding({GLFW_KEY_W})).move, glm::vec3(0, 0, 1));
    EXPECT_EQ(flyControls(holding({GLFW_KEY_S})).move, glm::vec3(0, 0, -1));
    EXPECT_EQ(flyControls(holding({GLFW_KEY_D})).move, glm::vec3(1, 0, 0));
    EXPECT_EQ(flyControls(holding({GLFW_KEY_A})).move, glm::vec3(-1, 0, 0));
    EXPECT_EQ(flyControls(holding({GLFW_KEY_E})).move, glm::vec3(0, 1, 0));
    EXPECT_EQ(flyControls(holding({GLFW_KEY_SPACE})).move, glm::vec3(0, 1, 0));
    EXPECT_EQ(flyControls(holding({GLFW_KEY_Q})).move, glm::vec3(0, -1, 0));
    EXPECT_EQ(flyControls(holding({GLFW_KEY_LEFT_CONTROL})).move, glm::vec3(0, -1, 0));
    EXPECT_EQ(flyControls(holding({GLFW_KEY_RIGHT_CONTROL})).move, glm::vec3(0, -1, 0));
    EXPECT_EQ(flyControls(holding({GLFW_KEY_W, GLFW_KEY_S, GLFW_KEY_A})).move, glm::vec3(-1, 0, 0));  // W, S cancel
    EXPECT_EQ(flyControls(holding({GLFW_KEY_LEFT})).turn, glm::vec2(1, 0));  // positive yaw turns left
    EXPECT_EQ(flyControls(holding({GLFW_KEY_RIGHT})).turn, glm::vec2(-1, 0));
    EXPECT_EQ(flyControls(holding({GLFW_KEY_UP})).turn, glm::vec2(0, 1));
    EXPECT_EQ(flyControls(holding({GLFW_KEY_DOWN})).turn, glm::vec2(0, -1));
    EXPECT_TRUE(flyControls(holding({GLFW_KEY_LEFT_SHIFT})).fast);
    EXPECT_TRUE(flyControls(holding({GLFW_KEY_RIGHT_SHIFT})).fast);
}

TEST(WindowKeys, FlyKeysAreExactlyTheKeysReadAndClashWithNoAction) {
    for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key) {
        const FlyControls c = flyControls([&](int k) { return k == key; });
        const bool read = c.move != glm::vec3(0.0f) || c.turn != glm::vec2(0.0f) || c.fast;
        const bool listed = std::find(flyKeys().begin(), flyKeys().end(), key) != flyKeys().end();
        EXPECT_EQ(read, listed) << "GLFW key " << key;
        if (listed) {
            EXPECT_EQ(actionForKey(key, false).action, WindowAction::None) << "GLFW key " << key;
            EXPECT_EQ(actionForKey(key, true).action, WindowAction::None) << "GLFW key " << key;
        }
    }
}

}  // namespace
}  // namespace racer
