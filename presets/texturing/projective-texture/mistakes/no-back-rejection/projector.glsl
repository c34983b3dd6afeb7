// EXERCISE — projective texture mapping (000_c9f7e5de708ecbb3.txt L2219-2232): a slide
// projector. Every world point is mapped into the projector's frustum by one 4x4 matrix, and
// the divided result looks up the slide. You write the bias matrix, the division and the test
// that keeps the projector from lighting what is behind it; the rest (the projector's view and
// projection, the lighting) is given.
//     passlab run   texturing/projective-texture --exercise presets/texturing/projective-texture/exercise
//     passlab grade texturing/projective-texture --exercise presets/texturing/projective-texture/exercise
//     (s, t, r, q) = B * P_proj * V_proj * (x, y, z, 1)
//     slide coordinates (s/q, t/q)
#ifndef PROJECTIVE_PROJECTOR_GLSL
#define PROJECTIVE_PROJECTOR_GLSL
#include "common/camera.glsl"

const float kDegrees = 0.01745329252;
const float kProjNear = 0.05, kProjFar = 50.0;   // the projector frustum's depth range

mat4 projector_matrix() {
    // TODO 1: the bias matrix B (L2227-2232: "express this as a projective transform"). The
    // projection leaves the frustum's x, y in [-1, 1] after the division by w; the slide is
    // addressed in [0, 1]. Write B so that, AFTER the division of TODO 2,
    //     s/q = 0.5 * x/w + 0.5,   t/q = 0.5 * y/w + 0.5,   q = w   (z can stay as it is)
    // B acts on the undivided (x, y, z, w): which entries put the + 0.5 in? (GLSL's mat4
    // constructor takes columns.)
    const mat4 kBias = mat4(0.5, 0.0, 0.0, 0.0,  0.0, 0.5, 0.0, 0.0,  0.0, 0.0, 1.0, 0.0,  0.5, 0.5, 0.0, 1.0);
    mat4 view = look_at(params.proj_pos, params.proj_target, vec3(0.0, 1.0, 0.0));
    mat4 proj = perspective(params.proj_fov * kDegrees, params.proj_aspect, kProjNear, kProjFar);
    return kBias * proj * view;
}

// The slide's coordinates of world point p, and whether the projector lights p at all.
bool projector_coords(vec3 p, out vec2 st) {
    vec4 stq = projector_matrix() * vec4(p, 1.0);
    // TODO 2: the slide coordinates of p (L2227-2232): the projective transform gives
    // homogeneous (s, t, r, q); the slide is read at
    //     (s/q, t/q)
    st = stq.xy / stq.w;
    bool inside = all(greaterThanEqual(st, vec2(0.0))) && all(lessThanEqual(st, vec2(1.0)));
    // TODO 3: the mask of points behind the projector. q is the projector's -z_view: positive
    // in front of it, negative behind, and a negative q flips (s, t) with it, so the division
    // of TODO 2 lands points behind the projector inside [0, 1] too (the backwards copy of the
    // slide). in_front must say whether the projector lights p; when params.mask_behind is
    // false the test is off on purpose (every p counts as in front: the bug, shown).
    bool in_front = true;  // the [0, 1] test above keeps p inside the frustum
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
