#version 450
// 002_644d46bdce7e5305.txt L641-654:
//   exposure = uExposure * autokey(L) / max(L, 1e-8)      (L: mean luminance, the 1x1 mip)
//   out = hejl(color * exposure)
// autokey is not defined in the document: see passes/post/tonemap.glsl for the one we chose.
#include "post/tonemap.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 mapped;
uniform sampler2D hdr;
uniform sampler2D lum;

const float kGamma = 2.2;

void main() {
    float stored = textureLod(lum, vec2(0.5), 16.0).r;  // past the last level: the 1x1 one
    float mean = params.mean == MEAN_LOG ? exp(stored) : stored;
    float exposure = params.exposure * (params.auto ? autokey(mean) / max(mean, 1e-8) : 1.0);
    vec3 c = texture(hdr, uv).rgb * exposure;
    int op = (params.split && uv.x < 0.5) ? OPERATOR_CLAMP : params.operator;
    vec3 o = op == OPERATOR_HEJL       ? tonemap_hejl(c)
             : op == OPERATOR_REINHARD ? pow(tonemap_reinhard(c), vec3(1.0 / kGamma))
                                       : pow(clamp(c, 0.0, 1.0), vec3(1.0 / kGamma));
    if (params.split && abs(uv.x - 0.5) < 0.0015) o = vec3(1.0, 0.8, 0.2);
    mapped = vec4(o, 1.0);
}
