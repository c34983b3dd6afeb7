#version 450
// Per pixel, the full mesh `a` against a simplified one `b` (both from lod.frag):
// r = 1 where exactly one of them covers the pixel (silhouette mismatch), g = |depth difference|
// in view units where both do, b = the largest |shading or uv difference| where both do.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D a;
uniform sampler2D b;
void main() {
    vec4 x = texelFetch(a, ivec2(gl_FragCoord.xy), 0), y = texelFetch(b, ivec2(gl_FragCoord.xy), 0);
    bool cx = x.a > 0.0, cy = y.a > 0.0;
    bool both = cx && cy;
    vec3 d = abs(x.rgb - y.rgb);
    color = vec4(cx != cy ? 1.0 : 0.0, both ? abs(x.a - y.a) : 0.0, both ? max(d.r, max(d.g, d.b)) : 0.0, 1.0);
}
