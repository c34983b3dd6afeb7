#version 450
// The deferred presets' scene: FLOOR draws the ground plane, otherwise the mesh is instanced
// over a jittered 8 x 8 grid (hash-placed sizes). World position, normal, and a per-object
// material (albedo, specular) to the fragment shader.
#include "common/hash.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out vec4 v_material;  // rgb albedo, a specular intensity

void main() {
#ifdef FLOOR
    vec3 p = position, n = normal;
    v_material = vec4(0.55, 0.55, 0.5, 0.1);
#else
    int i = gl_InstanceIndex;
    vec3 h = hash_pcg3(vec3(float(i), 2.0, 11.0));
    vec2 cell = vec2(float(i % 8), float(i / 8)) - 3.5;
    float s = 0.5 + 0.5 * h.z;
    vec3 offset = vec3((cell + (h.xy - 0.5) * 0.6) * 1.6, 0.0);
    vec3 p = position * s + vec3(offset.x, 0.5 * s, offset.y);
    vec3 n = normal;
    v_material = vec4(0.25 + 0.7 * hash_pcg3(vec3(float(i), 7.0, 1.0)), 0.6 * h.y);
#endif
    v_world = p;
    v_normal = n;
    gl_Position = frame.view_proj * vec4(p, 1.0);
}
