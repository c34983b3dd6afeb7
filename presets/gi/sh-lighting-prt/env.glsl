// The distant lighting environment L(w) the PRT preset projects into SH, and the scene's
// placements, shared by every pass of the graph.
#ifndef PRT_ENV_GLSL
#define PRT_ENV_GLSL

// params.env: the procedural sky (a low-frequency environment, what PRT is for: 000 L5448-5451),
// a constant (the l = 0 test), 0.5 + 0.3 y (bands 0 and 1, the round-trip test) and a
// polynomial of degree 2 with m != 0 terms (bands 0..2: the real form's sqrt(2) matters).
vec3 env_radiance_fixed(vec3 w) {
    if (params.env == ENV_CONSTANT) return vec3(params.env_value);
    if (params.env == ENV_LINEAR) return vec3(0.5 + 0.3 * w.y);
    if (params.env == ENV_POLY) return vec3(0.5 + 0.3 * w.y + 0.2 * w.x - 0.15 * w.z + 0.25 * w.x * w.z);
    // Sky: blue zenith, pale horizon, dark warm ground, and a broad sun lobe (exponent 8:
    // mostly below band 4, so 16 coefficients hold it) towards params.sun_dir.
    float up = w.y;
    vec3 sky = mix(vec3(0.35, 0.4, 0.5), vec3(0.1, 0.2, 0.5), clamp(up, 0.0, 1.0));
    vec3 ground = vec3(0.18, 0.14, 0.1);
    vec3 base = mix(ground, sky, smoothstep(-0.2, 0.1, up));
    float s = max(dot(w, normalize(params.sun_dir)), 0.0);
    return base + vec3(6.0, 4.8, 3.2) * pow(s, 8.0);
}

// The environment turned by params.env_yaw degrees about +y: L_rot(w) = L(R_y(-a) w).
mat3 env_yaw_matrix(float degrees) {
    float a = radians(degrees), c = cos(a), s = sin(a);
    return mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c);  // R_y(a), columns
}
vec3 env_radiance(vec3 w) { return env_radiance_fixed(transpose(env_yaw_matrix(params.env_yaw)) * w); }

// Scene: the teapot (mesh 0) standing on a floor plane (mesh 1). The teapot generator centres
// its bounding box; its base is 0.4828 below its origin (tests/graphs/bvh/scene.glsl).
const uint PRT_CAPACITY = 4096u;  // vertices per mesh in the buffers (teapot: 2592, floor: 1681)
const float TEAPOT_BASE = 0.4828;
vec3 prt_offset(uint mesh) { return mesh == 0u ? vec3(0.0, TEAPOT_BASE, 0.0) : vec3(0.0); }
mat4 prt_object_from_world(uint mesh) {
    vec3 o = prt_offset(mesh);
    return mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -o.x, -o.y, -o.z, 1);
}

#endif
