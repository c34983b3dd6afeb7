#version 450
// The room's five surfaces (room.glsl), one instance each, with the outputs of object.vert
// (the walls are receivers: shade.frag sees them as OBJECT = SHADOW_GROUND).
#include "shadows/room.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
void main() {
    mat4 model = room_model(gl_InstanceIndex);
    v_world = (model * vec4(position, 1.0)).xyz;
    v_normal = mat3(model) * normal;   // rotation times a scale along the plane: the normal keeps its direction
    gl_Position = frame.view_proj * vec4(v_world, 1.0);
}
