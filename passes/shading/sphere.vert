#version 450
// World-space normal and position of a mesh drawn at the origin (no model transform): the
// vertex stage of the sphere presets shading/blinn-phong-normalized and shading/fresnel.
// Outputs: location 0 the normal, location 1 the world position (note: passes/envmap/object.vert
// has the opposite order).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec3 v_world;
void main() {
    v_normal = normal;
    v_world = position;
    gl_Position = frame.view_proj * vec4(position, 1.0);
}
