#version 450
// r: Lambert shading of the interpolated normal, gb: uv, a: view depth (0 = no surface), so a
// comparison sees coverage, depth, normals and texture coordinates at once.
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec2 v_uv;
layout(location = 2) in float v_depth;
layout(location = 0) out vec4 color;
void main() {
    vec3 n = normalize(v_normal);
    color = vec4(max(dot(n, normalize(vec3(0.4, 0.8, 0.45))), 0.0), v_uv, v_depth);
}
