#version 450
// Analytic light sources (000_c9f7e5de708ecbb3.txt L830-878, L1296-1320), Lambert surface:
//   L_o = sum over k of f_r E_k cos(theta_k),   f_r = albedo / pi
//   point:        E = I / r^2 from p_l                               (L849-857, L1304-1314)
//   directional:  E constant, from direction d                       (L859-865)
//   spot:         a point light times a cone factor around d         (L869-877)
// The document gives the spot's inner and outer angles but no falloff between them; ours is
// smoothstep(cos theta_o, cos theta_i, dot(-l, d)) (docs/catalogue.md: say so).
// LIGHTS is a bit mask of the lights this pass adds: 1 point, 2 spot, 4 directional.
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 color;
#if LIGHTS == 7
layout(location = 1) out float spot;  // the cone factor, for the tests
#endif
const float kPi = 3.14159265;

float spot_factor(vec3 p) {
    vec3 l = normalize(params.spot_pos - p);
    return smoothstep(cos(radians(params.outer_deg)), cos(radians(params.inner_deg)), dot(-l, normalize(params.spot_dir)));
}

void main() {
    vec3 n = normalize(v_normal), p = v_world, f = params.albedo / kPi, c = vec3(0.0);
    if ((LIGHTS & 1) != 0 && params.point_on) {
        vec3 d = params.point_pos - p;
        float r2 = dot(d, d);
        c += f * params.point_power / r2 * max(dot(n, d / sqrt(r2)), 0.0);
    }
    if ((LIGHTS & 2) != 0 && params.spot_on) {
        vec3 d = params.spot_pos - p;
        float r2 = dot(d, d);
        c += f * params.spot_power / r2 * spot_factor(p) * max(dot(n, d / sqrt(r2)), 0.0);
    }
    if ((LIGHTS & 4) != 0 && params.dir_on) c += f * params.dir_power * max(dot(n, normalize(params.dir_dir)), 0.0);
    color = vec4(c, 1.0);
#if LIGHTS == 7
    spot = spot_factor(p);
#endif
}
