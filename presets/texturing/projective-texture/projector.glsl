// A slide projector (000_c9f7e5de708ecbb3.txt L2219-2223 "PTM simulates a video projector, or a
// flashlight, slide projector", L2227-2232: "map object coordinates to light frustum; express
// this as a projective transform; usually a 4x4 matrix"). The projector is a
// second camera built here from params with passes/common/camera.glsl:
//     (s, t, r, q) = B * P_proj * V_proj * (x, y, z, 1)
//     slide coordinates (s/q, t/q), B = scale-and-bias [-1, 1] -> [0, 1]
// Pitfall (docs/catalogue.md): a point BEHIND the projector has q = w_clip = -z_view < 0, and the
// division by a negative q mirrors it back into [0, 1]: without the q > 0 test every projector
// also throws an upside-down copy of the slide backwards. mask_behind = false shows that bug.
#ifndef PROJECTIVE_PROJECTOR_GLSL
#define PROJECTIVE_PROJECTOR_GLSL
#include "common/camera.glsl"

const float kDegrees = 0.01745329252;
const float kProjNear = 0.05, kProjFar = 50.0;   // the projector frustum's depth range

mat4 projector_matrix() {
    // B: x, y in [-1, 1] -> s, t in [0, 1] (the "bias" matrix of projective texturing)
    const mat4 kBias = mat4(0.5, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.5, 0.5, 0.0, 1.0);
    mat4 view = look_at(params.proj_pos, params.proj_target, vec3(0.0, 1.0, 0.0));
    mat4 proj = perspective(params.proj_fov * kDegrees, params.proj_aspect, kProjNear, kProjFar);
    return kBias * proj * view;
}

// The slide's coordinates of world point p, and whether the projector lights p at all.
bool projector_coords(vec3 p, out vec2 st) {
    vec4 stq = projector_matrix() * vec4(p, 1.0);
    st = stq.xy / stq.w;
    bool inside = all(greaterThanEqual(st, vec2(0.0))) && all(lessThanEqual(st, vec2(1.0)));
    bool in_front = stq.w > 0.0 || !params.mask_behind;   // the q < 0 mask
    return inside && in_front;
}

// Light the projector throws onto a surface point p with normal n: the slide's colour times
// the intensity and the cosine towards the projector (a point light shaped by the slide).
vec3 projector_light(sampler2D slide, vec3 p, vec3 n) {
    vec2 st;
    if (!projector_coords(p, st)) return vec3(0.0);
    vec3 l = normalize(params.proj_pos - p);
    return textureLod(slide, st, 0.0).rgb * params.intensity * max(dot(n, l), 0.0);
}
#endif
