#version 450
// The highlight-shape invariant (docs/catalogue.md, shading/phong), in the plane n = +z:
// theta_i = 60 deg, m = 100, v 5 degrees away from the mirror direction r, once rotated in the
// plane of incidence (towards n) and once out of it (about the axis r x y).
//   x = 0: Phong (v.r)^m, in plane        x = 1: Phong, out of plane      x = 2: |x0 - x1|
//   x = 3: Blinn-Phong (n.h)^m, in plane  x = 4: Blinn-Phong, out of plane x = 5: x3 / x4
// Phong's lobe depends only on the angle to r, so x0 = x1 = cos(5 deg)^100 = 0.68300 (the
// highlight is circular, 000 L975). The half vector moves 2.5 deg in plane but 4.994 deg out
// of it, so Blinn-Phong gives 0.90917 vs 0.68362: the lobe is 1.33x narrower across the plane,
// the stretched highlight of L980-988.
#include "common/brdf.glsl"
layout(location = 0) out float lobe;

const float kThetaI = radians(60.0);
const float kOffset = radians(5.0);
const float kM = 100.0;

// Rodrigues' rotation of v about the unit axis k by angle a.
vec3 rotate(vec3 v, vec3 k, float a) {
    return v * cos(a) + cross(k, v) * sin(a) + k * dot(k, v) * (1.0 - cos(a));
}

void main() {
    int x = int(gl_FragCoord.x);
    vec3 n = vec3(0.0, 0.0, 1.0);
    vec3 l = vec3(sin(kThetaI), 0.0, cos(kThetaI));
    vec3 r = phong_mirror(n, l);
    vec3 y = vec3(0.0, 1.0, 0.0);                       // normal of the plane of incidence
    vec3 v_in = rotate(r, y, kOffset);
    vec3 v_out = rotate(r, normalize(cross(r, y)), kOffset);
    float p_in = phong_lobe(v_in, r, kM), p_out = phong_lobe(v_out, r, kM);
    float b_in = blinn_phong_lobe(n, normalize(v_in + l), kM);
    float b_out = blinn_phong_lobe(n, normalize(v_out + l), kM);
    float values[6] = float[](p_in, p_out, abs(p_in - p_out), b_in, b_out, b_in / b_out);
    lobe = values[x];
}
