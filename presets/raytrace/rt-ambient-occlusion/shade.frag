#version 450
// Shading weighed by the traced visibility, as precomputed-ao shades with its baked one
// (000_c9f7e5de708ecbb3.txt L4867-4869): I = V (k_a I_a + k_d I_d max(n . l, 0)).
// V is traced at half resolution (trace.comp, STRIDE 2): AO texel q holds the surface at pixel
// 2q. Each pixel takes the four AO texels around it, bilinearly weighted, and keeps only those
// whose point lies on its own surface (joint bilateral upsampling: same normal, near its tangent
// plane), so V never bleeds across a silhouette from a surface behind.
layout(location = 0) in vec2 uv;
layout(location = 1) flat in vec3 v_light;  // rtao_light_direction(), from shade.vert
layout(location = 0) out vec4 hdr;
layout(location = 1) out vec4 ldr;  // the view: hdr clamped, to sRGB (issue #21: no display pass reading hdr back)
uniform sampler2D g_position;
uniform sampler2D g_normal;
uniform sampler2D ao;
#include "lighting.glsl"

float upsampled_visibility(ivec2 px, vec3 p, vec3 n) {
    vec2 f = (vec2(px) + 0.5) / 2.0 - 0.5;  // AO texel q sits at pixel 2q + 0.5: f in AO texels
    ivec2 q0 = ivec2(floor(f));
    vec2 t = f - vec2(q0);
    ivec2 top = textureSize(ao, 0) - 1, gtop = textureSize(g_position, 0) - 1;
    float sum = 0.0, weight = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 o = ivec2(k & 1, k >> 1), q = clamp(q0 + o, ivec2(0), top);
        vec4 qp = texelFetch(g_position, min(q * 2, gtop), 0);
        vec3 qn = texelFetch(g_normal, min(q * 2, gtop), 0).xyz;
        float bilinear = (o.x == 1 ? t.x : 1.0 - t.x) * (o.y == 1 ? t.y : 1.0 - t.y);
        // 0.02: a fiftieth of a unit off the tangent plane counts as another surface.
        float c = max(dot(qn, n), 0.0), c2 = c * c, c4 = c2 * c2;  // cos^8 (no pow: an exp and a log)
        float same = qp.w * float(abs(dot(qp.xyz - p, n)) < 0.02) * c4 * c4;
        sum += (bilinear + 1e-3) * same * texelFetch(ao, q, 0).r;
        weight += (bilinear + 1e-3) * same;
    }
    return weight > 0.0 ? sum / weight : texelFetch(ao, clamp(ivec2(px / 2), ivec2(0), top), 0).r;
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(g_position, px, 0);
    if (pos.w == 0.0) {
        hdr = vec4(0.62, 0.7, 0.82, 1.0);  // precomputed-ao's background
        ldr = vec4(clamp(hdr.rgb, 0.0, 1.0), 1.0);
        return;
    }
    vec4 gn = texelFetch(g_normal, px, 0);
    vec3 n = normalize(gn.xyz);
    float v = upsampled_visibility(px, pos.xyz, n);
    vec3 c = rtao_shade(v, n, int(gn.w + 0.5), v_light);
    hdr = vec4(params.show == SHOW_AO ? vec3(v) : c, 1.0);
    ldr = vec4(clamp(hdr.rgb, 0.0, 1.0), 1.0);
}
