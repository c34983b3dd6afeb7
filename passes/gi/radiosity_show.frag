#version 450
// Draws a light map over the patches of gi/radiosity_patches.glsl (000_c9f7e5de708ecbb3.txt
// L5072: "render using texture maps"): each fragment shows row RAD_ROW of the buffer `radiance`
// at its patch (radiosity: the last iterate; photon mapping: the baked density estimate); with
// params.interpolate bilinearly between the centres of the four nearest patches of the same
// surface (Gouraud-like smoothing, as radiosity images are usually shown), else flat.
#include "gi/radiosity_patches.glsl"

#ifndef RAD_ROW
#define RAD_ROW 0
#endif

layout(std430) readonly buffer Radiance { vec4 value[]; } radiance;

layout(location = 0) in vec3 object_pos;
layout(location = 1) flat in int instance;
layout(location = 0) out vec4 color;

// (radiance, 1) of a patch, (0, 0) for a hidden one (marked -1, under a block), so the
// interpolation leaves it out.
vec4 patch_radiance(RadSurface s, ivec2 c) {
    c = clamp(c, ivec2(0), ivec2(s.n - 1));
    vec3 l = radiance.value[(RAD_ROW) * RAD_PATCHES + s.first + c.y * s.n + c.x].rgb;
    return l.r < 0.0 ? vec4(0.0) : vec4(l, 1.0);
}

void main() {
    RadSurface s = radiosity_surface(radiosity_surface_of_hit(MESH, instance, object_pos));
    vec2 ab = radiosity_surface_coords(s, object_pos) * float(s.n);
    vec4 l;
    if (params.interpolate) {
        vec2 f = ab - 0.5;
        ivec2 c = ivec2(floor(f));
        vec2 w = f - vec2(c);
        l = mix(mix(patch_radiance(s, c), patch_radiance(s, c + ivec2(1, 0)), w.x),
                mix(patch_radiance(s, c + ivec2(0, 1)), patch_radiance(s, c + ivec2(1, 1)), w.x), w.y);
    } else {
        l = patch_radiance(s, ivec2(min(ab, vec2(s.n) - 0.5)));
    }
    color = vec4(l.rgb / max(l.a, 1e-6) * params.exposure, 1.0);
}
