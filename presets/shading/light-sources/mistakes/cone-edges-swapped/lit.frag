#version 450
// EXERCISE — analytic light sources (000_c9f7e5de708ecbb3.txt L830-878, L1296-1320) on a Lambert
// surface: each light sends light from one direction l_k to each point, so the rendering
// integral becomes a sum (L839-847, L1316-1320):
//     L_o = sum over k of f_r E_k cos(theta_k),   f_r = albedo / pi,   cos(theta_k) = max(n.l_k, 0)
// Builds on shading/lambert (f_r = c_d / pi and the cosine term). Fill in the four TODO blocks,
// then check your work against the reference:
//     passlab run   shading/light-sources --exercise presets/shading/light-sources/exercise
//     passlab grade shading/light-sources --exercise presets/shading/light-sources/exercise
// This one file renders every pass: LIGHTS is a bit mask of the lights the pass adds (1 point,
// 2 spot, 4 directional; 7 = all, in one pass); the multipass version adds them one per pass.
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 color;
#if LIGHTS == 7
layout(location = 1) out float spot;  // the cone factor, for the tests
#endif
const float kPi = 3.14159265;

// TODO 2: the spot's cone factor at the point p (L869-877): 1 inside the inner angle theta_i
// (params.inner_deg), 0 outside the outer angle theta_o (params.outer_deg), a smooth falloff
// between. The course names the two angles but no falloff; the reference uses GLSL's smoothstep
// on the cosine of the angle alpha between the cone axis d (params.spot_dir, not normalised) and
// the direction in which the light travels from params.spot_pos to p. Mind two things: a larger
// angle has a smaller cosine, and smoothstep(edge0, edge1, x) rises from edge0 to edge1.
float spot_factor(vec3 p) {
    vec3 l = normalize(params.spot_pos - p);
    return smoothstep(cos(radians(params.inner_deg)), cos(radians(params.outer_deg)), dot(-l, normalize(params.spot_dir)));
}

void main() {
    vec3 n = normalize(v_normal), p = v_world, f = params.albedo / kPi, c = vec3(0.0);
    if ((LIGHTS & 1) != 0 && params.point_on) {
        // TODO 1: the point light (L849-857, L1304-1314) at params.point_pos with intensity
        // I = params.point_power: the unit direction l towards it, its distance r, and
        //     E = I / r^2          (the inverse square law)
        // Add f_r E cos(theta) to c.
        vec3 d = params.point_pos - p;
        float r2 = dot(d, d);
        c += f * params.point_power / r2 * max(dot(n, d / sqrt(r2)), 0.0);
    }
    if ((LIGHTS & 2) != 0 && params.spot_on) {
        // TODO 3: the spot (L869-877) is a point light at params.spot_pos of intensity
        // params.spot_power, times its cone factor (TODO 2). Add its f_r E cos(theta) to c.
        vec3 d = params.spot_pos - p;
        float r2 = dot(d, d);
        c += f * params.spot_power / r2 * spot_factor(p) * max(dot(n, d / sqrt(r2)), 0.0);
    }
    if ((LIGHTS & 4) != 0 && params.dir_on) {
        // TODO 4: the directional light (L859-865): infinitely far, so one direction towards it
        // everywhere, params.dir_dir (a direction, not necessarily of length 1), and one
        // irradiance E = params.dir_power with no falloff. Add f_r E cos(theta) to c.
        c += f * params.dir_power * max(dot(n, normalize(params.dir_dir)), 0.0);
    }
    color = vec4(c, 1.0);
#if LIGHTS == 7
    spot = spot_factor(p);
#endif
}
