#version 450
// 16 x 16 samples per pixel of the same scene at this time (analytic), and both errors.
#include "aa/shapes.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ref;
layout(location = 1) out float err_taa;
layout(location = 2) out float err_cur;
uniform sampler2D taa;
uniform sampler2D cur;
uniform sampler2D ref_prev;
const int kRef = 16;
void main() {
    if (params.show != SHOW_ERROR) {  // 256 samples x 8 triangles: only when asked for
        ref = vec4(0.0), err_taa = err_cur = 0.0;
        return;
    }
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (frame.index > 0 && params.speed == 0.0) {
        ref = texelFetch(ref_prev, px, 0);  // still scene: computed once
    } else {
        // The triangles once per pixel, then 256 inside tests (shape_color_in gives what
        // shape_color_at would, bit for bit, without its cos/sin per vertex per sample).
        vec2 tri[kShapeTriangles * 3];
        bool solid[kShapeTriangles];
        shape_triangles(0, vec2(params.speed * frame.time, 0.0), tri, solid);
        vec3 sum = vec3(0.0);
        for (int y = 0; y < kRef; ++y)
            for (int x = 0; x < kRef; ++x)
                sum += shape_color_in(0, tri, solid, (gl_FragCoord.xy - 0.5 + (vec2(x, y) + 0.5) / float(kRef)) * frame.resolution.zw);
        ref = vec4(sum / float(kRef * kRef), 1.0);
    }
    err_taa = length(texelFetch(taa, px, 0).rgb - ref.rgb);
    err_cur = length(texelFetch(cur, px, 0).rgb - ref.rgb);
}
