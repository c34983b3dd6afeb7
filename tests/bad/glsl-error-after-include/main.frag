#version 450
#include "lib.glsl"
layout(location = 0) out vec4 color;
void main() {
    color = vec4(one() + colr);
}
