#version 450
// Four panels, left to right: A (to explain), B (source of patches), A rebuilt from B's
// patches (each pixel takes the centre of its match, B(f(a))) and the field's offsets
// f(a) - a coloured as in the course (003_cfc3b5b225ddab3d.txt L141-145, image/nnf.glsl).
#include "image/nnf.glsl"

layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D A;
uniform sampler2D B;
uniform sampler2D nnf_in;

void main() {
    vec2 px = uv * frame.resolution.xy;
    float panel = floor(frame.resolution.x / 4.0);
    ivec2 size = textureSize(A, 0);
    int k = int(px.x / panel);
    vec2 local = vec2(px.x - float(k) * panel, px.y - 0.5 * (frame.resolution.y - panel)) / panel;
    if (k > 3 || any(lessThan(local, vec2(0.02))) || any(greaterThan(local, vec2(0.98)))) {
        color = vec4(0.1, 0.1, 0.12, 1.0);
        return;
    }
    ivec2 p = clamp(ivec2((local - 0.02) / 0.96 * vec2(size)), ivec2(0), size - 1);
    vec4 f = texelFetch(nnf_in, p, 0);
    vec3 c;
    if (k == 0) c = texelFetch(A, p, 0).rgb;
    else if (k == 1) c = texelFetch(B, p, 0).rgb;
    else if (k == 2) c = texelFetch(B, nnf_target(f), 0).rgb;
    else c = nnf_color(vec2(nnf_target(f) - p), float(size.x) * 0.5);
    color = vec4(c, 1.0);
}
