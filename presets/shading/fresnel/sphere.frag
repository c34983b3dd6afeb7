#version 450
// The sphere shows R(theta) with theta the angle between the view ray and the normal: dark in
// the middle (R0 = 4% for glass) and bright at the silhouette, where light grazes.
#include "common/fresnel.glsl"
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec3 v_world;
layout(location = 0) out vec4 color;
void main() {
    vec3 n = normalize(v_normal);
    vec3 v = normalize(frame.camera_pos.xyz - v_world);
    float c = clamp(dot(n, v), 0.0, 1.0), f0 = fresnel_f0(params.n1, params.n2);
    float r = params.model == MODEL_SCHLICK ? fresnel_schlick(c, f0)
            : params.model == MODEL_SCHLICK_SG ? fresnel_schlick_sg(c, f0)
                                               : fresnel_exact(c, params.n1, params.n2);
    color = vec4(vec3(r), 1.0);
}
