#version 450
// EXERCISE — fill in TODO 2 and 3 (and TODO 1 in post/coc.glsl), then check your work:
//     passlab run   post/dof-coc-gather --exercise presets/post/dof-coc-gather/exercise
//     passlab grade post/dof-coc-gather --exercise presets/post/dof-coc-gather/exercise
// Gather (000_c9f7e5de708ecbb3.txt L3140-3148): each pixel averages neighbours on a disc of the
// largest blur radius around; a neighbour counts if its own circle of confusion reaches this
// pixel (scatter-as-gather). The problem the document names — "sharp foreground objects leak on
// blurry background" — is handled by its solution, depth-aware filtering: a neighbour behind
// this pixel may contribute only as far as this pixel's own circle reaches, so a blurred
// background does not smear over an in-focus object in front of it, nor the reverse.
// HALF_RES (the live default, `resolution = half`; not the document's, for a live frame rate on
// a CPU rasteriser): the same gather for one pixel of each 2x2 block (its top-left texel; the
// taps still read the full-resolution colour, CoC and depth and the radii stay in full-res
// pixels), into a view/2 target; display.frag composites it with the sharp input.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 result;
uniform sampler2D color;
uniform sampler2D coc;
uniform sampler2D depth;
const float kMaxRadius = 24.0;  // pixels
void main() {
#ifdef HALF_RES
    ivec2 px = 2 * ivec2(gl_FragCoord.xy), last = textureSize(color, 0) - 1;
    float h = float(textureSize(color, 0).y);  // full-res pixels per image height
#else
    ivec2 px = ivec2(gl_FragCoord.xy), last = textureSize(color, 0) - 1;
    float h = frame.resolution.y;
#endif
    float r_here = min(abs(texelFetch(coc, px, 0).x) * h, kMaxRadius);
    float d_here = texelFetch(depth, px, 0).r;
    vec3 sum = texelFetch(color, px, 0).rgb;
    float wsum = 1.0;
    int n = params.samples;
    for (int i = 0; i < n; ++i) {
        // A spiral over the disc of the largest radius (golden angle: even coverage).
        float fr = sqrt((float(i) + 0.5) / float(n)) * kMaxRadius, a = float(i) * 2.39996;
        ivec2 q = clamp(px + ivec2(round(fr * vec2(cos(a), sin(a)))), ivec2(0), last);
        float dist = length(vec2(q - px));
        float r_q = min(abs(texelFetch(coc, q, 0).x) * h, kMaxRadius);
        // TODO 2: scatter as gather (L3140-3143): tap q counts if its own circle of confusion
        // (radius reach, pixels) reaches this pixel at distance dist. w = 1 inside the circle,
        // 0 outside, with a one-pixel linear edge: 1 at dist = reach - 0.5 down to 0 at
        // dist = reach + 0.5.
        // TODO 3: depth-aware filtering (L3146-3148): a tap BEHIND this pixel (a larger
        // depth-buffer value than d_here) may reach it only as far as this pixel's own circle
        // r_here reaches, so a blurred background cannot smear over an in-focus object in
        // front of it. Set reach accordingly before computing w.
        float reach = texelFetch(depth, q, 0).r > d_here ? min(r_q, r_here) : r_q;
        float w = clamp(reach - dist + 0.5, 0.0, 1.0);
        sum += w * texelFetch(color, q, 0).rgb, wsum += w;
    }
    result = vec4(sum / wsum, 1.0);
}
