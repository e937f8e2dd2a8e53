// racer's window keys (game/src/window_keys.hpp): the key -> action mapping and the test
// key script's parser, without a window.
#include <GLFW/glfw3.h>

#include <algorithm>
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

TEST(WindowKeys, ScriptParsesAndSortsByFrame) {
    const auto keys = parseKeyScript("4:Esc,0:3,2:shift+T,1:c");
    ASSERT_EQ(keys.size(), 4u);
    EXPECT_EQ(keys[0].frame, 0);
    EXPECT_EQ(keys[0].key, GLFW_KEY_3);
    EXPECT_EQ(keys[1].key, GLFW_KEY_C);
    EXPECT_EQ(keys[2].key, GLFW_KEY_T);
    EXPECT_TRUE(keys[2].shift);
    EXPECT_EQ(keys[3].key, GLFW_KEY_ESCAPE);
    EXPECT_TRUE(parseKeyScript("").empty());
}

TEST(WindowKeys, BadScriptEntriesAreNamed) {
    for (const char* bad : {"3", "x:T", "-1:T", "2:Q", "2:9", "1:T,"}) {
        try {
            parseKeyScript(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const engine::Error& e) {
            EXPECT_NE(std::string(e.what()).find("--script entry"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace racer
