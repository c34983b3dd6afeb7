#version 450
// PRT shading (000 L5452-5453: "fast rendering (1 dot product)"): the outgoing radiance of a
// vertex is rho * (L . T), the environment's 16 SH coefficients against its baked transfer
// vector, per colour channel. MESH: 0 teapot, 1 floor.
layout(location = 0) in vec3 position;
layout(std430) readonly buffer Transfer { float t[]; } transfer;
layout(std430) readonly buffer EnvSh { vec4 c[16]; } env_sh;
layout(location = 0) out vec3 v_radiance;
#include "env.glsl"
void main() {
    uint i = uint(MESH) * PRT_CAPACITY + uint(gl_VertexIndex);
    vec3 dot_lt = vec3(0.0);
    for (uint k = 0u; k < 16u; ++k) dot_lt += env_sh.c[k].rgb * transfer.t[16u * i + k];
    vec3 rho = MESH == 0 ? params.albedo : params.floor_albedo;
    v_radiance = rho * dot_lt;
    gl_Position = frame.view_proj * vec4(position + prt_offset(uint(MESH)), 1.0);
}
