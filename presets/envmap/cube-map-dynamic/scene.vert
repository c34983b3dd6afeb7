#version 450
#ifdef VERTEX_LAYER
#extension GL_ARB_shader_viewport_layer_array : require
#endif
// Vertex stage of the scene (scene.glsl), in four versions chosen by defines:
//   CUBE_FACE_ITERATION: one face per pass iteration (repeat = 6, layer = "iteration"):
//                        clip = cube_face_clip(pl_iteration, ...), the face's 90 degree camera;
//   LAYERED:             world position only, the geometry shader (cube_layers.geom) projects
//                        every triangle onto all 6 faces in one pass;
//   VERTEX_LAYER:        one pass, no geometry shader: the draw has 6x the instances, instance
//                        k draws scene instance k % N into face k / N, and the vertex shader
//                        writes gl_Layer itself (Vulkan 1.2 shaderOutputLayer);
//   neither:             the main camera.
// ACTIVE (an expression) switches the cube-map version off without removing its pass.
#include "scene.glsl"
#include "envmap/cube_face_camera.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out int v_instance;
#ifndef ACTIVE
#define ACTIVE true
#endif
void main() {
#ifdef VERTEX_LAYER
    int i = gl_InstanceIndex % (kCubes + 1), face = gl_InstanceIndex / (kCubes + 1);
#else
    int i = gl_InstanceIndex;
#endif
    v_world = scene_world(position, i, frame.time);
    v_normal = scene_normal(normal, i, frame.time);
    v_instance = i;
#if defined(CUBE_FACE_ITERATION)
    gl_Position = cube_face_clip(pl_iteration, v_world - kCubeCentre, kCubeNear, kCubeFar);
#elif defined(VERTEX_LAYER)
    gl_Position = cube_face_clip(face, v_world - kCubeCentre, kCubeNear, kCubeFar);
    gl_Layer = face;
#elif defined(LAYERED)
    gl_Position = vec4(v_world, 1.0);  // unused: the geometry shader writes the clip position
#else
    gl_Position = frame.view_proj * vec4(v_world, 1.0);
#endif
    if (!(ACTIVE) || !scene_visible(i)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
