#version 450
// Forward shading of the same scene: every light, while drawing (000 L2784-2788). The material
// is rounded to 8 bits like the G-buffer's albedo image, so both paths light the same numbers.
// ACTIVE (an expression) skips the light loop when nobody looks at the result.
#include "deferred/lights.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in vec4 v_material;
layout(location = 0) out vec4 lit;
const float kShininess = 32.0;
#ifndef ACTIVE
#define ACTIVE true
#endif
void main() {
    if (!(ACTIVE)) {
        lit = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec3 n = normalize(v_normal);
    vec4 mat = round(v_material * 255.0) / 255.0;
    vec3 v = normalize(frame.camera_pos.xyz - v_world);
    vec3 c = params.ambient * mat.rgb;
    for (int i = 0; i < params.lights; ++i) c += shade_point_light(point_light(i, frame.time), v_world, n, v, mat.rgb, mat.a, kShininess);
    lit = vec4(c, 1.0);
}
