#version 450
// Exposure + Hejl (display-encoded, to a UNORM target) of the gather (composited with the
// sharp input at half resolution: composite.glsl); or the blur radius (red, full at 16
// px); or the tap pattern (each tap of the largest grid a dot on the unit disc / n-gon).
#include "post/tonemap.glsl"
#include "bokeh_taps.glsl"
#include "composite.glsl"
#ifndef TAPS_VIEW
#define TAPS_VIEW 1
#endif
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D color;
uniform sampler2D result;
uniform sampler2D blur;
uniform sampler2D taps;
void main() {
    // resolution = half: the gather composited with the sharp input below 1-2 px of blur
    // (composite.glsl; composite_check.frag tests it).
    // (Straight code and selects: the fetches here and in dof_composite are the same ones, one each.)
    vec4 sharp = textureLod(color, uv, 0.0), blurred = dof_composite(color, result, blur, uv);
    vec3 c = tonemap_hejl((params.show == SHOW_SHARP || (params.split && uv.x < 0.5) ? sharp : blurred).rgb * params.exposure);
    c = params.show == SHOW_BLUR ? vec3(texture(blur, uv).x / 16.0, 0.0, 0.0) : c;
#if TAPS_VIEW
    // Only in the pass display_taps (preset.toml: show = taps): lavapipe runs an untaken branch's
    // loops and fetches too, so the pass for the other views is compiled without this one.
    if (params.show == SHOW_TAPS) {
        // The square [-1.1, 1.1]^2 at the centre of the view; the n-gon's outline in grey.
        vec2 q = (gl_FragCoord.xy - 0.5 * frame.resolution.xy) / (0.45 * frame.resolution.y) * 1.0;
        q.y = -q.y;
        float edge = -1e9;
        for (int k = 0; k < params.ngon; ++k) {
            float a = 2.0 * PI * float(k) / float(params.ngon);
            edge = max(edge, dot(q, vec2(cos(a), sin(a))));
        }
        c = vec3(abs(edge - cos(PI / float(params.ngon))) < 0.006 ? 0.35 : 0.0);
        if (abs(length(q) - 1.0) < 0.004) c = vec3(0.15, 0.15, 0.3);
        ivec2 n = textureSize(taps, 0);
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x)
                if (length(texelFetch(taps, ivec2(x, y), 0).xy - q) < 0.015) c = vec3(1.0, 0.8, 0.3);
    }
#endif
    if (params.split && abs(uv.x - 0.5) < 0.0015) c = vec3(1.0, 0.8, 0.2);
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
