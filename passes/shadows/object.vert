#version 450
// One object of the shared scene (scene.glsl), chosen by the define OBJECT, through the pass's
// camera: the light's for a depth pass (camera = "light"), the view's for shading.
#include "shadows/scene.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
void main() {
    mat4 model = shadow_model(OBJECT);
    v_world = (model * vec4(position, 1.0)).xyz;
    v_normal = mat3(model) * normal;   // rotations and translations only: no inverse transpose needed
    gl_Position = frame.view_proj * vec4(v_world, 1.0);
}
