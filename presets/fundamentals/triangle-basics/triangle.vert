#version 450
// gl_Position is given directly in clip space (000_c9f7e5de708ecbb3.txt L53-185: the vertex
// stage's one duty); a colour per vertex is interpolated across the triangle.
layout(location = 0) out vec3 v_color;
void main() {
    const vec2 p[3] = vec2[](vec2(-0.8, 0.8), vec2(0.8, 0.8), vec2(0.0, -0.8));
    const vec3 c[3] = vec3[](vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1));
    gl_Position = vec4(p[gl_VertexIndex], 0.0, 1.0);
    v_color = c[gl_VertexIndex];
}
