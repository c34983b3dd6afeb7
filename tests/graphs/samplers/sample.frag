#version 450
// One sampler feature per output pixel; the expected values are derived in preset.toml.
layout(location = 0) out vec4 color;
uniform sampler2D ramp_linear;
uniform sampler2D ramp_repeat;
uniform sampler2D ramp_clamp;
uniform sampler2D ramp_mirror;
uniform sampler2D ramp_border;
uniform sampler2D checker8;
uniform sampler2DShadow dep_cmp;
uniform sampler2DArray arr;
uniform sampler3D vol;

void main() {
    int x = int(gl_FragCoord.x);
    const float v = 0.5;
    if (x == 0) color = texture(ramp_linear, vec2(0.5, v));
    else if (x == 1) color = texture(ramp_repeat, vec2(0.3, v));
    else if (x == 2) color = texture(ramp_repeat, vec2(1.25, v));
    else if (x == 3) color = texture(ramp_clamp, vec2(1.25, v));
    else if (x == 4) color = texture(ramp_mirror, vec2(1.25, v));
    else if (x == 5) color = texture(ramp_mirror, vec2(1.75, v));
    else if (x == 6) color = texture(ramp_border, vec2(1.25, v));
    else if (x == 7) color = textureLod(checker8, vec2(0.5), 3.0);
    else if (x == 8) color = vec4(texture(dep_cmp, vec3(0.5, 0.5, 0.4)));
    else if (x == 9) color = vec4(texture(dep_cmp, vec3(0.5, 0.5, 0.6)));
    else if (x == 10) color = texture(arr, vec3(0.5, 0.5, 2.0));
    else color = vec4(texture(vol, vec3(0.125, 0.125, 0.625)).r, texture(vol, vec3(0.125)).r, 0, 1);
}
