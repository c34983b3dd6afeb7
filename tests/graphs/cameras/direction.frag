#version 450
// Each texel of a cube face stores the world direction it looks along, from the face's inverse
// view-projection: uv (0, 0) is the top-left texel, ndc = uv * 2 - 1.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    vec4 world = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, 0.5, 1.0);
    color = vec4(normalize(world.xyz / world.w - frame.camera_pos.xyz), 1.0);
}
