#version 450
// The plane generator's [-1, 1]^2 square stretched to |x| <= half_width, -extent <= z <= 2,
// the same plane that ground.glsl ray-casts for the reference.
layout(location = 0) in vec3 position;
layout(location = 0) out vec2 v_t;
void main() {
    vec3 p = vec3(position.x * params.half_width, 0.0, mix(-params.extent, 2.0, 0.5 * position.z + 0.5));
    v_t = vec2(p.x, -p.z) * params.density;
    gl_Position = frame.view_proj * vec4(p, 1.0);
}
