#version 450
// A night scene for depth-of-field presets, ray-traced per pixel (camera at the origin looking
// down -z, 45 degree vertical field of view): small bright lights at many depths (what bokeh
// is about: a defocused highlight takes the shape of the aperture), a lit ball as the subject
// (its front at 4 m), and a dark wall at 14 m studded with lights. Writes HDR `color` and `depth` = (view
// depth z in metres, Vulkan depth-buffer value d for zn = 0.1, zf = 100; post/coc.glsl).
#include "common/hash.glsl"
#include "post/coc.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 depth;
const float kNear = 0.1, kFar = 100.0, kWall = 14.0, kCell = 1.0;  // metres
const float kLampRadiance = 40.0, kWallLightRadiance = 25.0;
const int kLamps = 7;
// Floating lamps (centre, radius) from 1.8 m to 10 m, and their colours.
const vec4 kLamp[kLamps] = vec4[](vec4(-1.05, 0.45, -1.8, 0.03), vec4(0.75, -0.5, -2.6, 0.035), vec4(-0.9, -0.55, -3.2, 0.04),
                                  vec4(1.9, 0.9, -6.0, 0.07), vec4(-2.6, 1.2, -7.5, 0.08), vec4(3.2, -1.3, -9.0, 0.09),
                                  vec4(-0.6, 1.5, -10.0, 0.1));
const vec3 kLampColor[kLamps] = vec3[](vec3(1.0, 0.75, 0.4), vec3(0.5, 0.8, 1.0), vec3(1.0, 0.45, 0.35), vec3(1.0, 0.9, 0.6),
                                       vec3(0.6, 1.0, 0.7), vec3(1.0, 0.6, 0.9), vec3(0.7, 0.75, 1.0));
const vec4 kBall = vec4(0.25, -0.15, -4.6, 0.6);  // its front at 4 m

// Ray from the origin along dir against a sphere: distance or -1.
float hit_sphere(vec3 dir, vec4 s) {
    float b = dot(dir, s.xyz), q = dot(s.xyz, s.xyz) - s.w * s.w, disc = b * b - q;
    return disc > 0.0 && b - sqrt(disc) > 0.0 ? b - sqrt(disc) : -1.0;
}

void main() {
    float t = tan(radians(22.5));
    vec3 dir = normalize(vec3((uv.x * 2.0 - 1.0) * t * frame.aspect, (1.0 - uv.y * 2.0) * t, -1.0));
    // The wall: dim panels, a light in some of its 1 m cells.
    float best = kWall / -dir.z;
    vec3 p = dir * best;
    vec2 cell = floor(p.xy / kCell);
    vec3 c = vec3(0.02, 0.022, 0.03) * (0.6 + 0.4 * hash_pcg(vec3(cell, 1.0)));
    vec3 h = hash_pcg3(vec3(cell, 2.0));
    if (h.x < 0.25 && length(p.xy - (cell + 0.2 + 0.6 * h.yz) * kCell) < 0.07)
        c = kWallLightRadiance * mix(vec3(1.0, 0.7, 0.4), vec3(0.6, 0.8, 1.0), h.y);
    for (int i = 0; i < kLamps; ++i) {
        float s = hit_sphere(dir, kLamp[i]);
        if (s > 0.0 && s < best) best = s, c = kLampRadiance * kLampColor[i];
    }
    float s = hit_sphere(dir, kBall);
    if (s > 0.0 && s < best) {
        best = s;
        vec3 n = normalize(dir * s - kBall.xyz);
        c = vec3(0.8, 0.55, 0.35) * (0.03 + 1.2 * max(dot(n, normalize(vec3(-0.5, 0.7, 0.6))), 0.0));
    }
    float z = -(dir * best).z;
    color = vec4(c, 1.0);
    depth = vec4(z, depth_buffer_value(z, kNear, kFar), 0.0, 1.0);
}
