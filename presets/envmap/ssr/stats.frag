#version 450
// Per pixel, the comparison of SSR with the planar reflection (the stencil method) on the mirror,
// averaged over the view by the `classes_mean` mips pass and divided out in ratio.frag:
//   r: a hit that SSR *can* get right: the point the mirror truly shows (`truth`, written by the
//      reference's reflected objects) is seen by the camera, or the truth is the sky (then the
//      right answer is a miss and a hit is false, e.g. behind an object); and the pixel is not on
//      an edge of the true reflection
//   g: r and a match: every displayed 8-bit channel within 4/255 (docs/catalogue.md)
//   b: any hit on the mirror (SSR's limitations included: 000 L4086-4120)
//   a: b and a match
#include "common/color.glsl"
layout(location = 0) out vec4 classes;  // per pixel, averaged by a mips pass
uniform sampler2D hdr;
uniform sampler2D reference;
uniform sampler2D gbuf;
uniform sampler2D ssr;
uniform sampler2D truth;   // xyz the reflected world point, w = 1 (0: the sky)
uniform sampler2D depth;
const float kMatch = 4.0 / 255.0;
// "The camera sees this point": its view depth agrees with the depth buffer where it projects to
// within 0.2% (1 cm at the mirror's distance): 1% let through the grazing underside of the
// teapot's foot, which the camera's image holds only as a pixel-thin line.
const float kVisible = 0.002;

// A pixel whose truth differs from a neighbour's by more than this (world units), or changes
// between sky and surface, sits on an edge of the true reflection: its colour depends on
// sub-pixel coverage, which neither method resolves.
const float kEdge = 0.05;
bool on_edge(ivec2 p) {
    vec4 t = texelFetch(truth, p, 0);
    ivec2 hi = textureSize(truth, 0) - 1;
    for (int k = 0; k < 4; ++k) {
        ivec2 q = clamp(p + ivec2(k == 0 ? 1 : k == 1 ? -1 : 0, k == 2 ? 1 : k == 3 ? -1 : 0), ivec2(0), hi);
        vec4 u = texelFetch(truth, q, 0);
        if (u.w != t.w || (t.w > 0.0 && distance(u.xyz, t.xyz) > kEdge)) return true;
    }
    return false;
}
float view_depth(float z) { vec4 v = frame.inv_proj * vec4(0.0, 0.0, z, 1.0); return -v.z / v.w; }

bool camera_sees(vec3 q) {
    vec4 c = frame.view_proj * vec4(q, 1.0);
    vec3 s = vec3(c.xy / c.w * 0.5 + 0.5, c.z / c.w);
    if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return false;
    float zb = texelFetch(depth, ivec2(s.xy * vec2(textureSize(depth, 0))), 0).r;
    return abs(view_depth(zb) - view_depth(s.z)) <= kVisible * view_depth(s.z);
}

// What the 8-bit output shows: envmap/display.frag's c / (1 + c/4), then the sRGB encoding.
vec3 displayed(vec3 c) { return linear_to_srgb(clamp(c / (1.0 + 0.25 * c), 0.0, 1.0)); }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    classes = vec4(0.0);
    if (texelFetch(gbuf, p, 0).w <= 0.0 || texelFetch(ssr, p, 0).a <= 0.0) return;  // not a hit on the mirror
    vec3 d = abs(displayed(texelFetch(hdr, p, 0).rgb) - displayed(texelFetch(reference, p, 0).rgb));
    float match = max(d.r, max(d.g, d.b)) <= kMatch ? 1.0 : 0.0;
    vec4 t = texelFetch(truth, p, 0);
    bool can_be_right = !(t.w > 0.0 && !camera_sees(t.xyz)) && !on_edge(p);
    classes = vec4(can_be_right ? 1.0 : 0.0, can_be_right ? match : 0.0, 1.0, match);
}
