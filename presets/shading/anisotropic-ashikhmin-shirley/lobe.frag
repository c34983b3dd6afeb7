#version 450
// The lobe in the local frame n = +z, t = +x, b = +y, theta_i = 45 deg; v is the mirror
// direction r turned 5 deg out of the plane of incidence (v+) or 5 deg the other way (v-).
//   x = 0  isotropic (e_u = e_v = 50), plane of incidence 30 deg from t:
//          |f(v+) - f(v-)| / f: the lobe is mirror-symmetric about the plane through r    -> 0
//   x = 1  isotropic: l and v turned together 70 deg about n, relative change             -> 0
//   x = 2  anisotropic (100, 10): the same mirror asymmetry                                 0.009115
//   x = 3  anisotropic: the same rotation                                                   0.121496
//   x = 4  anisotropic, plane along t: f(v moved 5 deg along t) / f(v moved 5 deg along b)
//          (e_u = 100 along t is the narrower direction)                                  0.820488
//   x = 5  largest relative |f(l, v) - f(v, l)| (specular + diffuse) over 4096 random pairs
//          and random tangent azimuths, e_u = 100, e_v = 10, R_s = 0.9                        -> 0
// Expected values from the formula evaluated in double precision (README).
#include "common/brdf.glsl"
#include "common/hash.glsl"
layout(location = 0) out float lobe;

const vec3 kN = vec3(0.0, 0.0, 1.0);
vec3 rotate(vec3 v, vec3 k, float a) {   // Rodrigues, k a unit axis
    return v * cos(a) + cross(k, v) * sin(a) + k * dot(k, v) * (1.0 - cos(a));
}
float f_spec(vec3 l, vec3 v, float e_u, float e_v, float azimuth_t) {
    vec3 t = vec3(cos(azimuth_t), sin(azimuth_t), 0.0), b = cross(kN, t);
    return ashikhmin_shirley_spec(kN, t, b, l, v, e_u, e_v, 1.0);
}
float f_full(vec3 l, vec3 v, float azimuth_t) {
    vec3 t = vec3(cos(azimuth_t), sin(azimuth_t), 0.0), b = cross(kN, t);
    return ashikhmin_shirley_spec(kN, t, b, l, v, 100.0, 10.0, 0.9)
         + ashikhmin_shirley_diffuse(vec3(1.0), 0.9, l.z, v.z).x;
}
void main() {
    int x = int(gl_FragCoord.x);
    float az = radians(x == 4 ? 0.0 : 30.0), ti = radians(45.0), d = radians(5.0);
    vec3 l = vec3(sin(ti) * cos(az), sin(ti) * sin(az), cos(ti));
    vec3 r = phong_mirror(kN, l);
    vec3 plane_normal = vec3(-sin(az), cos(az), 0.0);
    vec3 out_axis = normalize(cross(r, plane_normal));
    vec3 vp = rotate(r, out_axis, d), vm = rotate(r, out_axis, -d);
    float e_v = x <= 1 ? 50.0 : 10.0, e_u = x <= 1 ? 50.0 : 100.0;
    if (x == 0 || x == 2) {
        float a = f_spec(l, vp, e_u, e_v, 0.0), b = f_spec(l, vm, e_u, e_v, 0.0);
        lobe = abs(a - b) / max(a, b);
    } else if (x == 1 || x == 3) {
        float turn = radians(70.0);
        float a = f_spec(l, vp, e_u, e_v, 0.0), b = f_spec(rotate(l, kN, turn), rotate(vp, kN, turn), e_u, e_v, 0.0);
        lobe = abs(a - b) / max(a, b);
    } else if (x == 4) {
        vec3 v_t = rotate(r, plane_normal, d);              // in the plane: h moves along t
        lobe = f_spec(l, v_t, 100.0, 10.0, 0.0) / f_spec(l, vp, 100.0, 10.0, 0.0);
    } else {
        float worst = 0.0;
        for (int i = 0; i < 4096; ++i) {
            vec3 h1 = hash_pcg3(vec3(i, 1, 5)), h2 = hash_pcg3(vec3(i, 2, 5));
            float c1 = 0.02 + 0.98 * h1.x, c2 = 0.02 + 0.98 * h2.x;
            vec3 a = vec3(sqrt(1.0 - c1 * c1) * cos(6.2831853 * h1.y), sqrt(1.0 - c1 * c1) * sin(6.2831853 * h1.y), c1);
            vec3 bb = vec3(sqrt(1.0 - c2 * c2) * cos(6.2831853 * h2.y), sqrt(1.0 - c2 * c2) * sin(6.2831853 * h2.y), c2);
            float tz = 6.2831853 * h1.z;
            float fa = f_full(a, bb, tz), fb = f_full(bb, a, tz);
            worst = max(worst, abs(fa - fb) / max(1.0, max(fa, fb)));
        }
        lobe = worst;
    }
}
