#version 450
// First half of the error analysis: each texel sums one 16x16 block of pixels (two levels keep
// every loop far below lavapipe's silent 65535-iteration cut at any view size).
// Only pixels fully on the plane (reference coverage 1, filters' alpha 1) count.
//   sq  = sum of squared errors against the reference: (trilinear, hardware 16x, shader, count)
//   sum = sum of values: (reference, trilinear, hardware 16x, shader)
layout(location = 0) out vec4 sq;
layout(location = 1) out vec4 sum;
uniform sampler2D trilinear_img;
uniform sampler2D hardware_img;
uniform sampler2D shader_img;
uniform sampler2D reference_img;
float grey(vec4 c) { return dot(c.rgb, vec3(1.0 / 3.0)); }
void main() {
    ivec2 size = textureSize(reference_img, 0), base = ivec2(gl_FragCoord.xy) * 16;
    sq = vec4(0.0);
    sum = vec4(0.0);
    if (!params.analysis) return;   // the filter images are only partly evaluated (strips.glsl)
    for (int y = base.y; y < min(base.y + 16, size.y); ++y)
        for (int x = base.x; x < min(base.x + 16, size.x); ++x) {
            vec4 r = texelFetch(reference_img, ivec2(x, y), 0);
            vec4 a = texelFetch(trilinear_img, ivec2(x, y), 0);
            vec4 b = texelFetch(hardware_img, ivec2(x, y), 0);
            vec4 c = texelFetch(shader_img, ivec2(x, y), 0);
            if (r.a < 1.0 || a.a < 1.0) continue;
            vec3 e = vec3(grey(a), grey(b), grey(c)) - grey(r);
            sq += vec4(e * e, 1.0);
            sum += vec4(grey(r), grey(a), grey(b), grey(c));
        }
}
