#version 450
// Stage 4 of 002 L955-974: the flare (bilinearly upsampled) modulated by lens dirt plus a
// starburst rotated with the camera, added to the scene, then exposure, vignette and Hejl's
// filmic curve (which includes the display encoding: its output goes straight to the screen):
//   hejl(x) = x (6.2x + 0.5) / (x (6.2x + 1.7) + 0.06),  x = max(0, c - 0.004)
//   vignette = max(0, 1 - |0.5 - uv| / |(0.5, 0.5)|)^0.4
#include "post/tonemap.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 final;
uniform sampler2D hdr;
uniform sampler2D flare;
uniform sampler2D starburst;
uniform sampler2D dirt;

void main() {
    // 002 turns the starburst with the camera (an angle from its forward and up vectors), so it
    // does not look painted on the screen; the view matrix's rows are those vectors.
    vec3 forward = -vec3(frame.view[0][2], frame.view[1][2], frame.view[2][2]);
    vec3 up = vec3(frame.view[0][1], frame.view[1][1], frame.view[2][1]);
    float angle = (forward.x + up.z) * 3.14159 * 0.5;  // 002: (M[2].x + M[1].z) * pi / 2
    vec2 star_uv = mat2(cos(angle), -sin(angle), sin(angle), cos(angle)) * ((uv - 0.5) * vec2(frame.aspect, 1.0) * 0.5) + 0.5;
    vec3 lens_mod = params.lens_mod ? texture(dirt, uv).rgb + texture(starburst, star_uv).rgb : vec3(1.0);
    vec3 color = texture(hdr, uv).rgb + texture(flare, uv).rgb * lens_mod;
    float vignette = pow(max(0.0, 1.0 - length(vec2(0.5) - uv) / 0.70710678), 0.4);
    final = vec4(tonemap_hejl(color * params.exposure * vignette), 1.0);
}
