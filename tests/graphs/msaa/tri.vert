#version 450
// The lower-left half of the screen: vertices (-1,-1), (-1,1), (1,1) in Vulkan NDC (y down).
void main() {
    const vec2 p[3] = vec2[](vec2(-1, -1), vec2(-1, 1), vec2(1, 1));
    gl_Position = vec4(p[gl_VertexIndex], 0.5, 1.0);
}
