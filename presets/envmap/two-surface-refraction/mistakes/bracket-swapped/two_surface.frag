#version 450
// Two-surface refraction (004_9a40ad89bdfc582a.txt L763-854): the ray is bent where it enters
// (P1, front face) and again where it leaves (P2, back face), instead of leaving at once
// (the one-surface approximation of envmap/refraction-env).
//   1. T1 = refract(I, N1, 1/eta) at P1
//   2. P2 = P1 + d T1 (L780), d found by binary search against the back-face depth map
//      (L788-795): bracket A = P1, B = P1 + d_max T1 (camera space); M = (A + B)/2 projected
//      into the map gives d~; M still inside (in front of the back face) -> A = M, else B = M;
//      ~5 iterations (L784: "ca. 5 iterations suffice"). d = |(A + B)/2 - P1| at the end.
//   3. N2 from the back-face normal map at P2's pixel (L799-803), T2 = refract(T1, -N2, eta)
//   4. the environment in direction T2 (L805-808); Fresnel at P1 mixes in the reflection R1.
// SIGN CONVENTION (stated, not fixed silently): L793-794 read "if d~ > M_z set A = M" with
// camera-space points and t_z < 0. With camera-space z (negative in front of the eye) that test
// is backwards: a back face nearer than M (d~ > M_z, less negative) means M is already outside.
// The printed rule holds for depths as positive distances, which is what back_depth stores
// (-z_view): d~ > depth(M) -> M is in front of the back face, still inside -> A = M.
// Total internal reflection at P2 (refract returns 0): the ray would bounce inside; the method
// allows "2 intersection calculations per light ray" (figure, L840-842), so the internally reflected
// direction reflect(T1, -N2) goes to the environment directly.
// Outside the object's silhouette the map holds 0 (no back face): M is treated as outside.
#include "common/fresnel.glsl"
#include "safe_normal.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
layout(location = 1) out vec4 chord;   // sphere only: |d - chord| / chord, chord, |d - chord| / diameter, 1
layout(location = 2) out vec4 exit_dir;  // sphere only: |T2 - (2 (I.T1) T1 - I)|, 1 where T2 was refracted at a back face (tests)
uniform samplerCube env;
uniform sampler2D back_normal;
uniform sampler2D back_depth;

float depth_of(vec3 p) { return -(frame.view * vec4(p, 1.0)).z; }
ivec2 pixel_of(vec3 p) {
    vec4 c = frame.view_proj * vec4(p, 1.0);
    return clamp(ivec2((c.xy / c.w * 0.5 + 0.5) * frame.resolution.xy), ivec2(0), ivec2(frame.resolution.xy) - 1);
}

void main() {
    if (!(VISIBLE)) discard;
    vec3 P1 = v_world, I = normalize(P1 - frame.camera_pos.xyz);
    // Interpolated normals can face away from the eye on a front face near a silhouette (the
    // teapot's handle and spout); refract() would then reflect, even at eta = 1 (0.062 off the
    // background without this). Face them forward.
    // A zero normal (the teapot's lid knob and bottom poles are degenerate) takes the face's.
    vec3 n = safe_normal(v_normal, v_world);
    vec3 N1 = faceforward(n, I, n);
    float eta = params.eta;
    vec3 R1 = reflect(I, N1);
    float F1 = fresnel_exact(clamp(-dot(I, N1), 0.0, 1.0), 1.0, eta);
    vec3 T1 = refract(I, N1, 1.0 / eta);  // entering a denser medium: never total reflection
    vec3 T2 = T1;
    float d = 0.0;
    bool exited = false;  // T2 refracted at a back face (tests)
    if (params.surfaces == SURFACES_TWO) {
        // Binary search for the exit point along T1.
        vec3 A = P1, B = P1 + MAX_CHORD * T1;
        for (int i = 0; i < params.steps; ++i) {
            vec3 M = 0.5 * (A + B);
            float d_map = texelFetch(back_depth, pixel_of(M), 0).r;
            if (d_map > depth_of(M)) B = M;
            else A = M;
        }
        vec3 P2 = 0.5 * (A + B);
        d = distance(P2, P1);
        vec4 n2 = texelFetch(back_normal, pixel_of(P2), 0);
        if (n2.w > 0.0) {  // w = 0: no back face at P2's pixel (the teapot's open rim): leave T1
            vec3 N2 = normalize(n2.xyz);
            T2 = refract(T1, -N2, eta);  // leaving: glass -> air, the normal against the ray
            exited = dot(T2, T2) > 0.0;
            if (dot(T2, T2) == 0.0) T2 = reflect(T1, -N2);  // total internal reflection
        }
    }
    vec3 c = mix(texture(env, T2).rgb, texture(env, R1).rgb, F1);
    hdr = vec4(c, 1.0);
    // The sphere's analytic chord: entry point on the true sphere, chord = -2 T1.(P1 - centre).
    vec3 Ps = normalize(P1) * kSphereRadius;
    float chord_true = -2.0 * dot(T1, Ps);
    float err = abs(d - chord_true);
    chord = params.model == MODEL_SPHERE ? vec4(err / chord_true, chord_true, err / (2.0 * kSphereRadius), 1.0) : vec4(0.0);
    // A sphere is symmetric about the plane through its centre with normal T1, which swaps P1 and
    // P2: the ray leaves as the mirror image of the one that came in, T2 = 2 (I.T1) T1 - I.
    vec3 T2_sym = 2.0 * dot(I, T1) * T1 - I;
    exit_dir = params.model == MODEL_SPHERE && exited ? vec4(length(T2 - T2_sym), 1.0, 0.0, 1.0) : vec4(0.0);
}
