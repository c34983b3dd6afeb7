#version 450
// Four bands, top to bottom: repeat, mirror, clamp, border. Across the screen the texture
// coordinate runs over [-(span-1)/2, (span+1)/2], so [0,1] sits in the middle; white lines
// mark u = 0 and u = 1.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D repeat_nearest;
uniform sampler2D mirror_nearest;
uniform sampler2D clamp_nearest;
uniform sampler2D border_nearest;
uniform sampler2D repeat_linear;
uniform sampler2D mirror_linear;
uniform sampler2D clamp_linear;
uniform sampler2D border_linear;

void main() {
    int band = int(uv.y * 4.0);
    float span = params.span;
    vec2 t = vec2(uv.x * span - 0.5 * (span - 1.0), fract(uv.y * 4.0) * span * 0.5 - 0.25 * (span - 2.0));
    bool lin = params.filtering == FILTERING_LINEAR;
    vec3 c;
    if (band == 0) c = lin ? texture(repeat_linear, t).rgb : texture(repeat_nearest, t).rgb;
    else if (band == 1) c = lin ? texture(mirror_linear, t).rgb : texture(mirror_nearest, t).rgb;
    else if (band == 2) c = lin ? texture(clamp_linear, t).rgb : texture(clamp_nearest, t).rgb;
    else c = lin ? texture(border_linear, t).rgb : texture(border_nearest, t).rgb;
    float px = span / frame.resolution.x;
    if (abs(t.x) < px || abs(t.x - 1.0) < px) c = vec3(1.0);
    if (fract(uv.y * 4.0) < 0.01) c = vec3(0.3);
    color = vec4(c, 1.0);
}
