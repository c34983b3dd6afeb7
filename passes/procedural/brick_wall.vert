#version 450
// Wall vertex stage shared by presets/procedural/brick and presets/procedural/brick-noisy.
// The plane mesh lies in XZ; we stand it up (a rotation of -90 degrees about x) so that the
// wall's model coordinates are (x, y) = (position.x, -position.z), facing +Z.
// 004_9a40ad89bdfc582a.txt L141, L182-186: pass the model-space position to the fragment shader, so
// bricks stick to the object (world-space positions would make them swim when it moves).
layout(location = 0) in vec3 position;
layout(location = 0) out vec3 a_position_model;
layout(location = 1) out vec3 a_position_world;
layout(location = 2) out vec3 a_normal_world;
void main() {
    vec3 model = vec3(position.x, -position.z, 0.0);
    a_position_model = model;
    a_position_world = model;        // identity model-to-world here
    a_normal_world = vec3(0, 0, 1);
    gl_Position = frame.view_proj * vec4(model, 1.0);
}
