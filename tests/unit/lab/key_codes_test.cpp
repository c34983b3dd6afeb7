// The window's keys as Shadertoy's keyboard texture sees them: JavaScript keyCodes, and the
// down / pressed / toggled rows a press, a repeat and a release leave.
#include "key_codes.hpp"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

namespace pl::lab {
namespace {

using R = exec::KeyboardState;

TEST(KeyCodes, MatchJavaScript) {
    EXPECT_EQ(js_key_code(GLFW_KEY_A), 65);
    EXPECT_EQ(js_key_code(GLFW_KEY_Z), 90);
    EXPECT_EQ(js_key_code(GLFW_KEY_0), 48);
    EXPECT_EQ(js_key_code(GLFW_KEY_SPACE), 32);
    EXPECT_EQ(js_key_code(GLFW_KEY_LEFT), 37);
    EXPECT_EQ(js_key_code(GLFW_KEY_UP), 38);
    EXPECT_EQ(js_key_code(GLFW_KEY_RIGHT), 39);
    EXPECT_EQ(js_key_code(GLFW_KEY_DOWN), 40);
    EXPECT_EQ(js_key_code(GLFW_KEY_LEFT_SHIFT), 16);
    EXPECT_EQ(js_key_code(GLFW_KEY_F1), 112);
    EXPECT_EQ(js_key_code(GLFW_KEY_KP_5), 101);
    EXPECT_EQ(js_key_code(GLFW_KEY_UNKNOWN), -1);
}

TEST(KeyCodes, PressRepeatRelease) {
    R s;
    key_event(s, GLFW_KEY_A, GLFW_PRESS);
    EXPECT_TRUE(s.get(R::down, 65));
    EXPECT_TRUE(s.get(R::pressed, 65));
    EXPECT_TRUE(s.get(R::toggled, 65));
    EXPECT_FALSE(s.get(R::down, 66));
    s.clear(R::pressed);  // the frame saw it (as the window does after each frame)
    EXPECT_FALSE(s.get(R::pressed, 65));
    EXPECT_TRUE(s.get(R::down, 65));  // clear touches one row only
    key_event(s, GLFW_KEY_A, GLFW_REPEAT);
    EXPECT_FALSE(s.get(R::pressed, 65));  // auto-repeat is not a press
    key_event(s, GLFW_KEY_A, GLFW_RELEASE);
    EXPECT_FALSE(s.get(R::down, 65));
    EXPECT_TRUE(s.get(R::toggled, 65));
    key_event(s, GLFW_KEY_A, GLFW_PRESS);
    EXPECT_FALSE(s.get(R::toggled, 65));  // a second press toggles back
}

TEST(KeyCodes, HeldKeysOfATestCase) {
    R f0 = exec::held_keys({65, 255}, 0), f1 = exec::held_keys({65}, 1);
    EXPECT_TRUE(f0.get(R::down, 65) && f0.get(R::pressed, 65) && f0.get(R::toggled, 65));
    EXPECT_TRUE(f0.get(R::down, 255));
    EXPECT_EQ(f0.bits[7], 1u << 31);  // key 255 of row 0: the last bit of word 7
    EXPECT_TRUE(f1.get(R::down, 65) && !f1.get(R::pressed, 65) && f1.get(R::toggled, 65));
}

} // namespace
} // namespace pl::lab
