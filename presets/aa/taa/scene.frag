#version 450
// The shapes with what TAA needs besides colour (000 L3498-3505, L3521): a motion vector
// (how far this surface moved in uv since the last frame: the square moves speed * delta along
// x, the rest is still) and an object ID for history rejection.
#include "aa/shapes.glsl"
layout(location = 0) flat in vec3 v_color;
layout(location = 1) in vec2 v_uv;
layout(location = 2) flat in int v_triangle;
layout(location = 0) out vec4 cur;
layout(location = 1) out vec2 motion;
layout(location = 2) out float id;
void main() {
    bool square = v_triangle < 2;
    cur = vec4(v_color, 1.0);
    motion = square ? vec2(params.speed * frame.delta, 0.0) : vec2(0.0);
    id = square ? 1.0 : 2.0;
}
