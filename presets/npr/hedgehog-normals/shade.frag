#version 450
// Pass 1 (004_9a40ad89bdfc582a.txt L1146: "render geometry regularly"): Lambert with a sky
// ambient, so the hedgehog's lines have a surface to stand on.
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 color;
void main() {
    vec3 n = normalize(gl_FrontFacing ? v_normal : -v_normal);
    float key = max(dot(n, normalize(vec3(0.5, 0.8, 0.4))), 0.0);
    color = vec4(vec3(0.62, 0.6, 0.57) * (0.25 + 0.3 * n.y + 0.6 * key), 1.0);
}
