#version 450
// The G-buffer draw of one mesh of the scene (MESH: 0 teapot, 1 floor), moved by this frame's
// sub-pixel jitter (aa/taa_jitter.glsl, Halton(2,3)) so that the TAA stage sees new sub-pixel
// positions every frame (000 L3437-3444).
#include "scene.glsl"
#include "aa/taa_jitter.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;

void main() {
    mat4 object_from_world_m = object_from_world(uint(MESH));
    vec3 p = position - object_from_world_m[3].xyz;  // the placements are translations
    v_world = p;
    v_normal = normal;
    gl_Position = frame.view_proj * vec4(p, 1.0);
    gl_Position.xy += 2.0 * taa_jitter(frame.index, params.jitter) / frame.target.xy * gl_Position.w;
}
