#version 450
// The environment behind everything: the cube map in the world-space view direction.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
#ifdef SECOND_TARGET
layout(location = 1) out vec4 SECOND_TARGET;  // the background alone, for comparisons
#endif
uniform samplerCube env;
void main() {
    vec4 w = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    vec3 dir = normalize(w.xyz / w.w - frame.camera_pos.xyz);
    hdr = vec4(texture(env, dir).rgb, 1.0);
#ifdef SECOND_TARGET
    SECOND_TARGET = hdr;
#endif
}
