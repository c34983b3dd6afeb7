#version 450
#include "tint.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    color = vec4(tint(uv) * params.gain * /*KNOB*/1.0, 1.0);
}
