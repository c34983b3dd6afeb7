#version 450
// The Cornell box's instances for a draw pass, wall planes (MESH = 0) or blocks (MESH = 1), placed
// as gi/cornell.glsl says; the fragment gets the object-space position and the instance, and the world position and normal (the
// radiosity light map and the photon-map gather look their surface up from them).
#include "gi/cornell.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 object_pos;
layout(location = 1) flat out int instance;
layout(location = 2) out vec3 world_pos;
layout(location = 3) out vec3 world_normal;  // inverse transpose: the blocks are scaled non-uniformly

void main() {
    mat4 m = MESH == 0 ? cornell_wall(gl_InstanceIndex) : cornell_block(gl_InstanceIndex);
    object_pos = position;
    instance = gl_InstanceIndex;
    world_pos = (m * vec4(position, 1.0)).xyz;
    world_normal = transpose(inverse(mat3(m))) * normal;
    gl_Position = frame.view_proj * vec4(world_pos, 1.0);
}
