#version 450
// The environment, or the irradiance map itself (show = irradiance), in the view direction. The
// sky is evaluated directly (the 32 x 32 cube the convolution reads is too coarse to look at).
#include "envmap/sky.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
uniform samplerCube env;
uniform samplerCube irradiance;
void main() {
    vec4 w = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    vec3 dir = normalize(w.xyz / w.w - frame.camera_pos.xyz);
    vec3 c = params.env == ENV_SKY ? sky_radiance(dir, params.sun_dir, 1.0) : texture(env, dir).rgb;
    hdr = vec4(params.show == SHOW_IRRADIANCE ? texture(irradiance, dir).rgb / 3.14159265 : c, 1.0);
}
