// GLFW key -> the JavaScript keyCode Shadertoy's keyboard texture is indexed by, and the key
// events that maintain exec::KeyboardState (down / pressed this frame / toggled).
#pragma once

#include "exec/keyboard.hpp"

namespace pl::lab {

// -1 for keys Shadertoy's keyCodes do not name (or GLFW_KEY_UNKNOWN).
int js_key_code(int glfw_key);

// One GLFW key event (action: GLFW_PRESS, GLFW_RELEASE, GLFW_REPEAT). A press sets down and
// pressed and flips toggled; a repeat changes nothing (Shadertoy ignores auto-repeat); a release
// clears down. `pressed` is cleared by the caller once a frame has seen it.
void key_event(exec::KeyboardState& s, int glfw_key, int action);

} // namespace pl::lab
