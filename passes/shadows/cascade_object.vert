#version 450
// One object of the shared scene into cascade pl_iteration of the layered map (a depth pass with
// repeat = cascades and depth layer = "iteration"), through that cascade's matrix.
#include "shadows/scene.glsl"
#include "shadows/cascades.glsl"
layout(location = 0) in vec3 position;
layout(std430) readonly buffer Cascades { ShadowCascade c[SHADOW_MAX_CASCADES]; } cascades_in;
void main() {
    gl_Position = cascades_in.c[pl_iteration].view_proj * (shadow_model(OBJECT) * vec4(position, 1.0));
}
