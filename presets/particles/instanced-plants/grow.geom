#version 450
// Grows one plant per input point (000_c9f7e5de708ecbb3.txt L204-206, L224-225): a stem of
// SEGMENTS quads along the curve s(t) = (bend t^2, height t, 0), tapering from `width` to 0.2
// `width`, and `leaves` diamond leaves at t_k = (k + 1) / (leaves + 1), alternating sides. All of
// it from the species' parameters; the instance contributes only where the plant stands (its
// root and heading). PATCH: instead of the world, each plant is drawn in its own tile of the
// target in its local frame (the per-instance patch that compare.comp compares).
#include "plants.glsl"
#define SEGMENTS 8
#define MAX_LEAVES 6
layout(points) in;
layout(triangle_strip, max_vertices = 42) out;   // stem 2 (SEGMENTS + 1) + 4 per leaf
layout(location = 0) flat in int v_instance[];
layout(location = 0) out vec3 g_color;

vec3 stem(PlPlant p, float t) { return vec3(p.bend * t * t, p.height * t, 0.0); }

void put(vec3 local, vec3 color) {
    int i = v_instance[0];
#if PATCH
    // Tile i of a (GRID_X x PLANTS/GRID_X) grid, the local frame x in [-0.7, 0.7], y in [0, 1.4]
    // (z dropped: a side view). Snapped to 2^-12 in NDC so the tile offset (a multiple of 2/8
    // and 2/4) adds exactly: a patch rasterises the same in every tile.
    vec2 tile = vec2(i % GRID_X, i / GRID_X);
    vec2 ndc = vec2(local.x / 0.7, 1.0 - local.y / 0.7) * 0.5;   // [-0.5, 0.5] x [-0.5 .. 0.5]
    ndc = round(ndc * 4096.0) / 4096.0;
    vec2 size = vec2(2.0 / float(GRID_X), 2.0 / float(PLANTS / GRID_X));
    gl_Position = vec4(-1.0 + size * (tile + 0.5 + ndc), 0.5, 1.0);
#else
    float a = plant_heading(i), c = cos(a), s = sin(a);
    vec3 w = plant_root(i) + vec3(c * local.x + s * local.z, local.y, -s * local.x + c * local.z);
    gl_Position = frame.view_proj * vec4(w, 1.0);
#endif
    g_color = color;
    EmitVertex();
}

void main() {
    PlPlant p = plant_params(plant_species(v_instance[0]));
    vec3 stem_color = vec3(0.35, 0.5, 0.2), leaf_color = vec3(0.25, 0.62, 0.2);
    for (int k = 0; k <= SEGMENTS; ++k) {
        float t = float(k) / float(SEGMENTS);
        vec3 c = stem(p, t);
        vec3 tangent = normalize(vec3(2.0 * p.bend * t, p.height, 0.0));
        vec3 side = vec3(tangent.y, -tangent.x, 0.0) * p.width * (1.0 - 0.8 * t);
        put(c - side, stem_color * (0.7 + 0.3 * t));
        put(c + side, stem_color * (0.7 + 0.3 * t));
    }
    EndPrimitive();
    for (int k = 0; k < min(p.leaves, MAX_LEAVES); ++k) {
        float t = float(k + 1) / float(p.leaves + 1);
        vec3 base = stem(p, t);
        float dir = (k % 2 == 0) ? 1.0 : -1.0;
        vec3 along = normalize(vec3(dir, 0.6, dir * 0.3)) * p.leaf * (1.0 - 0.4 * t);
        vec3 across = vec3(-along.y, along.x, 0.0) * 0.25;
        vec3 shade = leaf_color * (0.8 + 0.2 * t);
        put(base, shade);
        put(base + 0.5 * along - across, shade * 0.9);
        put(base + 0.5 * along + across, shade * 1.1);
        put(base + along, shade);
        EndPrimitive();
    }
}
