#version 450
// Ground truth: the same scene evaluated analytically at 16 x 16 samples per pixel (256, as the
// document's comparison image, 000 L3316-3319), and the error of the SSAA result against it.
#include "aa/shapes.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 reference;
layout(location = 1) out vec4 error;
uniform sampler2D result;
const int kRef = 16;
void main() {
    // 256 samples x 8 triangles per pixel is slow on a CPU rasteriser: only when it is shown.
    if (params.show == SHOW_RESULT) {
        reference = error = vec4(0.0);
        return;
    }
    // The triangles once per pixel, then 256 inside tests (shape_color_in = shape_color_at).
    vec2 tri[kShapeTriangles * 3];
    bool solid[kShapeTriangles];
    shape_triangles(params.scene, vec2(0.0), tri, solid);
    vec3 sum = vec3(0.0);
    for (int y = 0; y < kRef; ++y)
        for (int x = 0; x < kRef; ++x) {
            vec2 p = (gl_FragCoord.xy - 0.5 + (vec2(x, y) + 0.5) / float(kRef)) * frame.resolution.zw;
            sum += shape_color_in(params.scene, tri, solid, p);
        }
    reference = vec4(sum / float(kRef * kRef), 1.0);
    error = vec4(abs(texelFetch(result, ivec2(gl_FragCoord.xy), 0).rgb - reference.rgb), 1.0);
}
