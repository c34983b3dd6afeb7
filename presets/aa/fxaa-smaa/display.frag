#version 450
// A magnified region (passes/aa/zoom.glsl), split: left the aliased image, right the chosen
// mode; or |result - reference| x 4.
#include "aa/zoom.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D unjittered;
uniform sampler2D result;
uniform sampler2D errors;
void main() {
    bool left_half;
    ivec2 t = aa_zoom_texel(uv, params.split, params.zoom, params.centre, frame.resolution.xy, left_half);
    vec3 c = left_half ? texelFetch(unjittered, t, 0).rgb : texelFetch(result, t, 0).rgb;
    if (!left_half && params.show == SHOW_ERROR) c = vec3(texelFetch(errors, t, 0).y * 4.0);
    if (aa_zoom_divider(uv, params.split)) c = vec3(1.0, 0.8, 0.2);
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
