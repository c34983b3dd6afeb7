#version 450
// The environment behind everything, in the world-space view direction (lookup.glsl).
#include "lookup.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
void main() {
    vec4 w = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    hdr = vec4(environment(w.xyz / w.w - frame.camera_pos.xyz), 1.0);
}
