#version 450
// Vertex stage of the solid-texture presets (marble-and-wood, procedural-bump): the model-space
// position goes to the fragment shader, which evaluates the 3D texture there (004 L128-200).
// Instance i stands at instance_centre(i) and moves rigidly by MOTION (passes/procedural/
// rigid.glsl). With CARRIED defined (an expression, true to draw) the camera rides along with
// the motion: the clip position is view_proj * M^-1 * M * p, written as view_proj * p since
// M^-1 M = I exactly, while the fragment still gets the moved world position and normal. So a
// carried image must not change with MOTION as long as the shading reads only object-space
// values and what moves with the object (light and camera are carried too, in the fragment).
// With ACTIVE defined (an expression) the pass draws nothing unless it is true: every vertex
// goes outside the clip volume, so a test-only pass costs no fragment work when it is off.
#include "procedural/rigid.glsl"
#ifndef MOTION
#define MOTION 0.0
#endif
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 a_position_model;
layout(location = 1) out vec3 a_position_world;
layout(location = 2) out vec3 a_normal_world;
layout(location = 3) flat out int a_instance;
void main() {
    RigidMotion m = rigid_motion(MOTION);
    vec3 centre = instance_centre(gl_InstanceIndex);
    a_position_model = position;
    a_position_world = rigid_apply(m, centre, centre + position);
    a_normal_world = m.rotation * normal;
    a_instance = gl_InstanceIndex;
#ifdef CARRIED
    gl_Position = (CARRIED) ? frame.view_proj * vec4(centre + position, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
#else
    gl_Position = frame.view_proj * vec4(a_position_world, 1.0);
#endif
#ifdef ACTIVE
    if (!(ACTIVE)) gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
#endif
}
