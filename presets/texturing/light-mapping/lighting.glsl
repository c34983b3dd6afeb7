// The static lighting of the floor, evaluated by the bake (into the light map), by the
// per-pixel reference, and for the ball: two point lights, Lambert, and the ball's shadow
// (an analytic ray-sphere test; "can take global effects (shadows, radiosity) into account",
// 000_c9f7e5de708ecbb3.txt L2168).
//     E(p, n) = sum_k I_k max(n . l_k, 0) / |L_k - p|^2 * V_k(p)       (irradiance / pi omitted)
#ifndef LIGHT_MAPPING_LIGHTING_GLSL
#define LIGHT_MAPPING_LIGHTING_GLSL

const float kFloorSize = 4.0;                  // the plane mesh: size 4, y = 0
const vec4 kBall = vec4(0.1, 0.45, 0.0, 0.3);  // occluder: centre, radius

// Lightmap parametrisation = the plane's own uv, (u, v) -> ((u - 0.5) S, 0, (v - 0.5) S)
// (host/scene/generators.cpp): unique over the floor, which a light map needs. The surface
// texture uses uv * tiles instead (repeating), as a second UV set would.
vec3 floor_position(vec2 uv) { return vec3((uv.x - 0.5) * kFloorSize, 0.0, (uv.y - 0.5) * kFloorSize); }

// Does the segment p -> q hit the ball? (|p + t (q - p) - c|^2 = r^2 for some t in (0, 1))
bool ball_blocks(vec3 p, vec3 q) {
    vec3 d = q - p, m = p - kBall.xyz;
    float a = dot(d, d), b = dot(m, d), c = dot(m, m) - kBall.w * kBall.w;
    float disc = b * b - a * c;
    if (disc < 0.0) return false;
    float t = (-b - sqrt(disc)) / a;
    return t > 1e-4 && t < 1.0;
}

vec3 point_light(vec3 p, vec3 n, vec3 pos, vec3 color, bool shadows) {
    vec3 l = pos - p;
    float r2 = dot(l, l);
    if (shadows && ball_blocks(p, pos)) return vec3(0.0);
    return color * max(dot(n, l * inversesqrt(r2)), 0.0) / r2;
}

vec3 irradiance(vec3 p, vec3 n, bool shadows) {
    return point_light(p, n, params.light0_pos, params.light0_color, shadows) +
           point_light(p, n, params.light1_pos, params.light1_color, shadows) + params.ambient;
}
#endif
