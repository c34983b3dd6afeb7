#version 450
// One step of the onion-peel fill (003_cfc3b5b225ddab3d.txt L65-91: Efros-Leung sampling with
// the rest of the picture as the source, image/efros_leung.glsl). Layer L fills the unknown
// texels that touch a texel known before it (the hole's current border), each from the known
// texels of its window only, so the hole closes from its border inwards, layer by layer.
// A texel's alpha is the layer that filled it plus one (a8 = 1 for the known picture, 0 for
// unknown): layer L sees as known exactly 1 <= a8 <= L, and a texel filled by another thread of
// the same layer (a8 = L + 1) never counts, whatever the timing. A layer may be cut into `parts`
// classes, (x + 5 y) % parts (diagonal, so a straight border spreads over every class), done in
// successive steps (the live view: one a frame). A layer never reads itself, and every split
// keeps the invariants, but the pictures differ (presets/image/image-completion/README.md).
// Step g = frame.accum_frame * pl_iteration_count + pl_iteration is part g % parts of layer
// g / parts + 1.
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D known;
uniform sampler2D valid;
layout(rgba8) uniform image2D canvas;
#ifdef GUIDE
// presets/image/patch-reshuffle: where a texel is not known yet, the guide (the marked segment
// scaled up) stands in for it with the weight params.guide_weight (alpha > 0 where it exists),
// so the fill follows the enlarged structure with the picture's own texels.
uniform sampler2D guide;
#endif

int g_layer;

int a8_at(ivec2 p) {
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, imageSize(canvas)))) return 0;
    return int(round(imageLoad(canvas, p).a * 255.0));
}
bool known_at(ivec2 p) { int a = a8_at(p); return a >= 1 && a <= g_layer; }

// One load: the alpha and the colour of the same texel come from the same read. The alpha
// returned is the texel's weight in d (image/efros_leung.glsl): 1 known, 0 unknown.
vec4 el_canvas(ivec2 p) {
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, imageSize(canvas)))) return vec4(0.0);
    vec4 c = imageLoad(canvas, p);
    int a = int(round(c.a * 255.0));
    if (a >= 1 && a <= g_layer) return vec4(c.rgb, 1.0);
#ifdef GUIDE
    vec4 gd = texelFetch(guide, p, 0);
    if (gd.a > 0.0) return vec4(gd.rgb, params.guide_weight);
#endif
    return vec4(0.0);
}
bool el_valid(ivec2 q) {
    // TODO 2 (003_cfc3b5b225ddab3d.txt L65-79): q may be a candidate centre only if its whole
    // N x N window is known picture: inside the image and outside the hole. The bake pass
    // `valid` stores exactly that (r = 1) in the image `valid`: read it with texelFetch.
    return false;
}

#include "image/efros_leung.glsl"

// The front of layer L: unknown, with at least one of its 8 neighbours known before L.
bool in_front(ivec2 p) {
    // TODO 1 (onion peel, L65-79): p is in the front of layer g_layer when it is still unknown
    // (a8_at(p) == 0) and at least one of its 8 neighbours is known before this layer
    // (known_at). Everything else is left alone: known texels are never rewritten.
    return false;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(canvas)))) return;
    int g = frame.accum_frame * pl_iteration_count + pl_iteration;
    g_layer = g / params.parts + 1;
    if ((p.x + 5 * p.y) % params.parts != g % params.parts || !in_front(p)) return;
    el_gather(p, params.half_window);
    ivec2 q = el_choose(known, params.epsilon, uvec3(p, uint(params.seed) * 65537u));
    imageStore(canvas, p, vec4(texelFetch(known, q, 0).rgb, float(g_layer + 1) / 255.0));
}
