#version 450
// What is shown: one filter over the whole view, or (split) four vertical strips, left to right:
// trilinear | hardware 16x | shader N taps | 256-spp reference. Sky where the plane is absent.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D trilinear_img;
uniform sampler2D hardware_img;
uniform sampler2D shader_img;
uniform sampler2D reference_img;
#include "strips.glsl"
void main() {
    int which = shown_filter(uv.x);
    vec4 c = which == SHOW_TRILINEAR ? texture(trilinear_img, uv)
           : which == SHOW_HARDWARE ? texture(hardware_img, uv)
           : which == SHOW_SHADER ? texture(shader_img, uv)
                                  : texture(reference_img, uv);
    const vec3 kSky = vec3(0.55, 0.65, 0.8);
    vec3 rgb = mix(kSky, c.rgb, c.a);
    if (params.show == SHOW_SPLIT && abs(fract(uv.x * 4.0 + 0.5) - 0.5) * frame.resolution.x * 0.25 < 1.0 && uv.x > 0.01 && uv.x < 0.99)
        rgb = vec3(1.0, 0.8, 0.2);
    color = vec4(rgb, 1.0);
}
