#version 450
// G-buffer for the rays (000_c9f7e5de708ecbb3.txt L5762: "Raytracing of shadows, ambient
// occlusion" launched from rasterised surfaces): world position and normal per pixel.
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in float v_id;
layout(location = 0) out vec4 g_position;  // xyz world, w = 1 on a surface (0: sky)
layout(location = 1) out vec4 g_normal;    // xyz unit normal facing the eye, w = patch id

void main() {
    vec3 n = normalize(v_normal);
    // The bowl's inside and outside coincide (precomputed-ao): keep the side facing the eye.
    if (dot(n, frame.camera_pos.xyz - v_world) < 0.0) discard;
    g_position = vec4(v_world, 1.0);
    g_normal = vec4(n, v_id);
}
