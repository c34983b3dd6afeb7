// Hierarchical-Z occlusion test of a box against a max-Z pyramid (000_c9f7e5de708ecbb3.txt
// L6292-6301): "a pixel represents max. z-value of group of pixels on lower level"; "if polygon
// is further than recorded pixel, early exit". Here the "polygon" is an object's bounding box:
// its nearest depth against the pyramid's farthest depth over the box's screen rectangle, at the
// level where that rectangle spans at most 2x2 texels, so the test is four fetches.
// Depth is Vulkan's 0 (near) .. 1 (far), depth test `less`.
#ifndef PASSLAB_HIZ_GLSL
#define PASSLAB_HIZ_GLSL

// The screen footprint of a box: the pixel rectangle [lo, hi] covering its 8 projected corners
// and their nearest depth. `ok` is false when a corner is behind the eye (w <= 0: the box
// straddles the camera plane and has no bounded rectangle), which a caller must treat as visible.
struct PlScreenRect { ivec2 lo; ivec2 hi; float zmin; bool ok; };

PlScreenRect pl_screen_rect(vec3 centre, vec3 half_size, mat4 view_proj, vec2 size) {
    PlScreenRect r;
    vec2 lo = vec2(1e30), hi = vec2(-1e30);
    r.zmin = 1.0;
    r.ok = true;
    for (int k = 0; k < 8; ++k) {
        vec3 s = vec3(k & 1, (k >> 1) & 1, (k >> 2) & 1) * 2.0 - 1.0;
        vec4 c = view_proj * vec4(centre + s * half_size, 1.0);
        if (c.w <= 0.0) { r.ok = false; return r; }
        vec3 ndc = c.xyz / c.w;
        vec2 px = (ndc.xy * 0.5 + 0.5) * size;   // frame.view_proj already flips y: row 0 is the top
        lo = min(lo, px); hi = max(hi, px);
        r.zmin = min(r.zmin, ndc.z);
    }
    // Pixels whose centres the rectangle may cover, clamped to the screen.
    r.lo = clamp(ivec2(floor(lo)), ivec2(0), ivec2(size) - 1);
    r.hi = clamp(ivec2(ceil(hi)), ivec2(0), ivec2(size) - 1);
    r.zmin = max(r.zmin, 0.0);
    return r;
}

// The level whose texels are at least as large as the rectangle's longer side, so the rectangle
// spans at most 2 texels per axis (level k texel = 2^k pixels), minus `refine` levels: each
// finer level doubles the texels fetched per axis (at most 2^refine + 1) and tightens the test,
// since coarse texels reach beyond the rectangle into what is drawn around it.
int pl_hiz_level(PlScreenRect r, int levels, int refine) {
    ivec2 e = r.hi - r.lo + 1;
    int k = int(ceil(log2(float(max(e.x, e.y))))) - refine;
    return clamp(k, 0, levels - 1);
}

// Level k's size by Vulkan's rule, max(size_0 >> k, 1), instead of textureSize(hiz, k): on
// lavapipe (Mesa 22.3.6) textureSize with a lod that differs between invocations returned the
// wrong level's size (20x11 for level 4 of 640x360), which clamped rectangles onto the wrong
// texels and culled 3 visible boxes (texturing/mipmapping/means.frag met the same in a
// fragment shader).
ivec2 pl_level_size(sampler2D s, int k) { return max(textureSize(s, 0) >> k, ivec2(1)); }

// The farthest depth the pyramid holds over the rectangle at level k. Level-0 pixel t lies under
// level-k texel min(t >> k, size_k - 1): floor halving gives the last texel of an odd side the
// dropped row/column too (post/max_reduce.frag), so the same clamp is used here.
float pl_hiz_max(sampler2D hiz, PlScreenRect r, int k) {
    // TODO (000_c9f7e5de708ecbb3.txt L6292-6301: "a pixel represents max. z-value of group of
    // pixels on lower level"): the farthest depth over EVERY level-k texel under the rectangle
    // r.lo .. r.hi. Level-0 pixel t lies under texel min(t >> k, pl_level_size(hiz, k) - 1);
    // read each with texelFetch(hiz, c, k) and return the maximum.
    return 1.0;   // nothing is ever occluded
}

// Occluded: the box's nearest point is farther than everything drawn over its rectangle.
bool pl_hiz_occluded(sampler2D hiz, PlScreenRect r, int k) {
    return r.ok && r.zmin > pl_hiz_max(hiz, r, k);
}
#endif
