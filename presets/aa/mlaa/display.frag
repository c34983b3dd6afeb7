#version 450
// A magnified region (nearest: pixels stay squares), optionally split: left the aliased input,
// right the chosen view. Edges: red = vertical (left side), green = horizontal (top side) over
// the dimmed image. Weights: the four blend weights (x2 so 0.5 is full). Error: |MLAA -
// reference| x 4 (largest channel).
#include "aa/zoom.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D color;
uniform sampler2D result;
uniform sampler2D edges;
uniform sampler2D weights;
uniform sampler2D errors;
void main() {
    bool left_half;
    ivec2 t = aa_zoom_texel(uv, params.split, params.zoom, params.centre, frame.resolution.xy, left_half);
    vec3 c = texelFetch(result, t, 0).rgb;
    if (left_half || params.show == SHOW_INPUT) c = texelFetch(color, t, 0).rgb;
    else if (params.show == SHOW_EDGES) c = 0.3 * texelFetch(color, t, 0).rgb + vec3(texelFetch(edges, t, 0).rg, 0.0);
    else if (params.show == SHOW_WEIGHTS) {
        vec4 w = texelFetch(weights, t, 0);
        c = 2.0 * vec3(w.x + w.y, w.z + w.w, 0.0);
    } else if (params.show == SHOW_ERROR) c = vec3(texelFetch(errors, t, 0).y * 4.0);
    if (aa_zoom_divider(uv, params.split)) c = vec3(1.0, 0.8, 0.2);
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
