#version 450
// The skin (SHELL undefined), or shell k = pl_iteration + 1 of params.shells: the surface offset
// along its normal by k / shells of the fur length, "done easily using the vertex shader"
// (004_9a40ad89bdfc582a.txt L1071-1072).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec2 v_uv;
layout(location = 2) out float v_height;
void main() {
#if SHELL
    v_height = float(pl_iteration + 1) / float(params.shells);
#else
    v_height = 0.0;
#endif
    v_normal = normal;
    v_uv = uv;
    gl_Position = frame.view_proj * vec4(position + normal * (params.fur_length * v_height), 1.0);
}
