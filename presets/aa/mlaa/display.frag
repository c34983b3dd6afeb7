#version 450
// A magnified region (nearest: pixels stay squares), optionally split: left the aliased input,
// right the chosen view. Edges: red = vertical (left side), green = horizontal (top side) over
// the dimmed image. Weights: the four blend weights (x2 so 0.5 is full). Error: |MLAA -
// reference| x 4 (largest channel).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D color;
uniform sampler2D result;
uniform sampler2D edges;
uniform sampler2D weights;
uniform sampler2D errors;
void main() {
    bool left_half = params.split && uv.x < 0.5;
    vec2 local = params.split ? vec2(fract(uv.x * 2.0), uv.y) : uv;
    vec2 extent = vec2(params.split ? 0.5 : 1.0, 1.0) / params.zoom;  // the region's size (uv)
    vec2 q = clamp(params.centre, 0.5 * extent, 1.0 - 0.5 * extent) + (local - 0.5) * extent;
    ivec2 t = clamp(ivec2(floor(q * frame.resolution.xy)), ivec2(0), ivec2(frame.resolution.xy) - 1);
    vec3 c = texelFetch(result, t, 0).rgb;
    if (left_half || params.show == SHOW_INPUT) c = texelFetch(color, t, 0).rgb;
    else if (params.show == SHOW_EDGES) c = 0.3 * texelFetch(color, t, 0).rgb + vec3(texelFetch(edges, t, 0).rg, 0.0);
    else if (params.show == SHOW_WEIGHTS) {
        vec4 w = texelFetch(weights, t, 0);
        c = 2.0 * vec3(w.x + w.y, w.z + w.w, 0.0);
    } else if (params.show == SHOW_ERROR) c = vec3(texelFetch(errors, t, 0).y * 4.0);
    if (params.split && abs(uv.x - 0.5) < 0.0015) c = vec3(1.0, 0.8, 0.2);
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
