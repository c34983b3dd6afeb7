#version 450
// One object of the mirror scene (scene.glsl), drawn either as itself or reflected.
//   OBJECT     index into object_model (0 teapot, 1 ball, 2 box)
//   MIRRORED   1: the reflected object M p for the stencil method (000 L3869-3870:
//              "Scale(1, 1, -1)" and "adapt culling to mirroring"; the pass sets
//              front_face = "cw" because det M = -1 turns counter-clockwise triangles clockwise)
//   VIEW_PROJ  the camera (default: the view's; the render-to-texture pass gives the mirrored one)
//   CLIP       1: gl_ClipDistance[0] = signed distance of the *unreflected* point to the mirror
//              plane, so whatever lies behind the mirror is cut away (needs shader_clip_distance);
//              switched by params.clip unless CLIP_ALWAYS is defined
//   VISIBLE    an expression; false parks the object outside the view volume
// Outputs the unreflected world position and normal: shading happens in the real world, seen
// from the eye the reflection implies (mirror_point(eye)), which is what a mirror shows.
#include "mirror/mirror.glsl"
#include "mirror/scene.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
#ifndef MIRRORED
#define MIRRORED 0
#endif
#ifndef VIEW_PROJ
#define VIEW_PROJ frame.view_proj
#endif
#ifndef CLIP
#define CLIP 0
#endif
#ifndef VISIBLE
#define VISIBLE true
#endif
#if CLIP
out gl_PerVertex { vec4 gl_Position; float gl_ClipDistance[1]; };
#endif
void main() {
    mat4 model = object_model(OBJECT);
    vec3 p = (model * vec4(position, 1.0)).xyz;
    v_world = p;
    v_normal = mat3(model) * normal;
#if MIRRORED
    vec4 q = mirror_matrix() * vec4(p, 1.0);
#else
    vec4 q = vec4(p, 1.0);
#endif
    gl_Position = (VIEW_PROJ) * q;
#if CLIP
#ifdef CLIP_ALWAYS
    gl_ClipDistance[0] = mirror_side(p);
#else
    gl_ClipDistance[0] = params.clip ? mirror_side(p) : 1.0;  // the preset's `clip` param
#endif
#endif
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
