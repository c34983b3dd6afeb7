#version 450
// Environment mapping (000_c9f7e5de708ecbb3.txt L2260-2364; 001_fe43b953f362fae7.txt L32-147):
// the environment is assumed infinitely far (or the object a point), so a lookup depends on
// the direction only:
//     R = V - 2 (N.V) N            V from the eye to the surface, all in world space
//     color = mix(decal, env(R), reflectivity)
// Pitfall (docs/catalogue.md): R must be in the map's space. Computed in eye space it needs the
// inverse of the view's 3x3 first; here everything is world space from the start.
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
uniform samplerCube env;
void main() {
    vec3 n = normalize(v_normal), V = normalize(v_world - frame.camera_pos.xyz);
    vec3 R = V - 2.0 * dot(n, V) * n;
    hdr = vec4(mix(params.decal, texture(env, R).rgb, params.reflectivity), 1.0);
}
