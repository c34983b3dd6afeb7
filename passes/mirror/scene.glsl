// The small scene the mirror presets share: a teapot, a ball and a tilted box that sinks through
// the mirror plane (so clipping at the plane matters), a stone frame around the mirror, under the
// procedural sky of envmap/sky.glsl. Shading is one sun (Lambert + optional Blinn-Phong) plus a
// hemispherical sky term; the specular term is view dependent, which is why SSR's test turns it
// off (a reflection re-uses the colour the *camera* saw).
#ifndef PASSLAB_MIRROR_SCENE_GLSL
#define PASSLAB_MIRROR_SCENE_GLSL
#include "envmap/sky.glsl"

const vec3 kSunDir = vec3(0.45, 0.7, 0.35);  // towards the sun (normalised where used)
const vec3 kSunColor = vec3(2.2, 2.0, 1.8);
const int kObjects = 3;                      // teapot, ball, box
const vec3 kAlbedo[kObjects] = vec3[](vec3(0.75, 0.32, 0.12), vec3(0.15, 0.45, 0.8), vec3(0.3, 0.7, 0.25));
const vec3 kFrameAlbedo = vec3(0.2, 0.19, 0.18);
const float kFrameHalf = 1.75, kFrameY = -0.01;  // the frame lies 1 cm below the mirror

mat4 translate(vec3 t) { return mat4(vec4(1, 0, 0, 0), vec4(0, 1, 0, 0), vec4(0, 0, 1, 0), vec4(t, 1)); }
mat4 rotate_y(float a) { float c = cos(a), s = sin(a); return mat4(vec4(c, 0, -s, 0), vec4(0, 1, 0, 0), vec4(s, 0, c, 0), vec4(0, 0, 0, 1)); }
mat4 rotate_z(float a) { float c = cos(a), s = sin(a); return mat4(vec4(c, s, 0, 0), vec4(-s, c, 0, 0), vec4(0, 0, 1, 0), vec4(0, 0, 0, 1)); }
mat4 rotate_x(float a) { float c = cos(a), s = sin(a); return mat4(vec4(1, 0, 0, 0), vec4(0, c, s, 0), vec4(0, -s, c, 0), vec4(0, 0, 0, 1)); }

// Model matrices (rigid: normals transform by the upper 3x3). The teapot generator centres its
// bounding box with height 0.9654 (3.15 x 2 / 6.525), so +0.4827 stands it on the floor. The box
// (side 0.6, half-diagonal 0.42) leans 34 degrees sideways with its centre 0.05 above the floor:
// one lower edge dips about 0.3 below the mirror.
mat4 object_model(int i) {
    if (i == 0) return translate(vec3(0.0, 0.4827, -0.1)) * rotate_y(0.5);
    if (i == 1) return translate(vec3(0.85, 0.35, 0.55));
    return translate(vec3(-0.9, 0.05, 0.45)) * rotate_y(0.3) * rotate_z(0.6);
}

// Radiance leaving p with normal n towards eye.
vec3 shade(vec3 p, vec3 n, vec3 eye, vec3 albedo, float specular) {
    n = normalize(n);
    vec3 l = normalize(kSunDir), v = normalize(eye - p), h = normalize(l + v);
    float ndl = max(dot(n, l), 0.0);
    vec3 sky = mix(vec3(0.16, 0.14, 0.12), vec3(0.35, 0.45, 0.6), 0.5 + 0.5 * n.y);  // hemisphere
    vec3 c = albedo * (kSunColor * ndl + sky);
    if (specular > 0.0 && ndl > 0.0) c += specular * kSunColor * pow(max(dot(n, h), 0.0), 64.0);
    return c;
}
vec3 sky_color(vec3 d) { return sky_radiance(d, kSunDir, 1.0); }
#endif
