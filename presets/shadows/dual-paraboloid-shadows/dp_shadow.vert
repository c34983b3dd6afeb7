#version 450
// One object of the shared scene (OBJECT) or the room (ROOM, instanced) warped into paraboloid
// map pl_iteration (repeat = 2: "two passes instead of six", 000 L4737), shadows/paraboloid.glsl.
#include "shadows/scene.glsl"
#include "shadows/room.glsl"
#include "shadows/paraboloid.glsl"
layout(location = 0) in vec3 position;
out float gl_ClipDistance[1];
void main() {
#ifdef ROOM
    mat4 model = room_model(gl_InstanceIndex);
#else
    mat4 model = shadow_model(OBJECT);
#endif
    vec3 world = (model * vec4(position, 1.0)).xyz;
    float clip_distance;
    gl_Position = dp_shadow_clip(world, params.light_pos, pl_iteration, DP_NEAR, DP_FAR, clip_distance);
    gl_ClipDistance[0] = clip_distance;
}
