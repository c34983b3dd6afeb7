// Horizon mapping at run time (001_fe43b953f362fae7.txt L965-975: "interpolate horizon values,
// shadow accordingly"): the light's tangent-space direction l gives its azimuth phi and
// elevation beta = asin(l.z); the horizon alpha(phi) is interpolated linearly between the two
// baked azimuths around phi (bump/horizon_bake.frag, 8 of them, pi/4 apart). The texel sees the
// light when beta > alpha(phi); a band of +-softness radians blurs the shadow edge (the baked
// angles are coarse in phi, so a hard edge would show the 8 directions).
#ifndef PASSLAB_HORIZON_GLSL
#define PASSLAB_HORIZON_GLSL
float horizon_angle(sampler2D horizon_a, sampler2D horizon_b, vec2 t, float phi) {
    const float kPi = 3.14159265358979;
    vec4 a = texture(horizon_a, t), b = texture(horizon_b, t);
    float alpha[8] = float[](a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w);
    float s = mod(phi, 2.0 * kPi) / (kPi / 4.0);   // in [0, 8)
    int k0 = int(floor(s)) % 8, k1 = (k0 + 1) % 8;
    return mix(alpha[k0], alpha[k1], fract(s));
}
// 1: lit, 0: in the relief's shadow.
float horizon_shadow(sampler2D horizon_a, sampler2D horizon_b, vec2 t, vec3 l_ts, float softness) {
    float beta = asin(clamp(l_ts.z, -1.0, 1.0));
    float alpha = horizon_angle(horizon_a, horizon_b, t, atan(l_ts.y, l_ts.x));
    return smoothstep(alpha - softness, alpha + softness, beta);
}
#endif
