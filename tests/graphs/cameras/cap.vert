#version 450
// A triangle of directions (w = 0) around -Z: points at infinity, as a shadow volume's dark cap.
void main() {
    const vec3 dirs[3] = vec3[](vec3(-1, -1, -1), vec3(1, -1, -1), vec3(0, 1, -1));
    gl_Position = frame.view_proj * vec4(dirs[gl_VertexIndex], 0.0);
}
