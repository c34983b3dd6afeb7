#version 450
// The same region twice, magnified with nearest filtering so pixels show as squares: left the
// plain render, right the MSAA resolve
// (resolve.frag's).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D res_shader;   // resolve.frag's mean of the 4 samples (equal to the hardware's `res`)
uniform sampler2D plain;
void main() {
    vec2 local = params.split ? vec2(fract(uv.x * 2.0), uv.y) : uv;
    vec2 q = params.centre + (local - 0.5) / params.zoom;
    ivec2 texel = ivec2(floor(q * frame.resolution.xy));
    vec3 c = params.split && uv.x < 0.5 ? texelFetch(plain, texel, 0).rgb : texelFetch(res_shader, texel, 0).rgb;
    if (params.split && abs(uv.x - 0.5) < 0.0015) c = vec3(1.0, 0.8, 0.2);
    ldr = vec4(c, 1.0);
}
