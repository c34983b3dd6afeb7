// EXERCISE — this file shadows the preset's sort_blend.glsl for oit/per-pixel-linked-lists only.
//     passlab run   presets/oit/per-pixel-linked-lists --exercise presets/oit/per-pixel-linked-lists/exercise
//     passlab grade presets/oit/per-pixel-linked-lists --exercise presets/oit/per-pixel-linked-lists/exercise
// Per-pixel linked lists, "Sorting and Blending" (000_c9f7e5de708ecbb3.txt L4316-4319): "Blend
// fragments back to front in PS; must sort by depth value in temp. array". The temporary array
// holds MAX_FRAGS entries (the pitfall: it caps the depth complexity); `cap` = params.max_frags
// <= MAX_FRAGS is how many the resolve keeps: the nearest ones.
float ppll_z[MAX_FRAGS];   // depths, ascending: ppll_z[0] is the nearest fragment
uint  ppll_c[MAX_FRAGS];   // packUnorm4x8 colours, in the same order
int   ppll_n = 0;          // how many are held

// Insert one fragment (insertion sort, one step per list node). A full array keeps its `cap`
// nearest fragments: a farther one is dropped, a nearer one replaces the farthest.
void ppll_insert(int cap, float z, uint rgba) {
    // TODO 1: the sort (000_c9f7e5de708ecbb3.txt L4319, "must sort by depth value in temp.
    // array"). Keep ppll_z[0..ppll_n) ascending (nearest first) with ppll_c in step. While
    // ppll_n < cap the fragment is added; when full, a fragment farther than ppll_z[ppll_n - 1]
    // is dropped and a nearer one replaces that farthest entry. Then move it to its place.
    // As shipped the fragment is appended in list order (the order the GPU appended them).
    if (ppll_n < cap) { ppll_z[ppll_n] = z; ppll_c[ppll_n] = rgba; ++ppll_n; }
}

// Composite the held fragments over `behind` (the opaque colour): back to front, the farthest
// (index ppll_n - 1) first, each with oit_over (composite.glsl).
vec3 ppll_blend(vec3 behind) {
    vec3 c = behind;
    // TODO 2: the blend (000_c9f7e5de708ecbb3.txt L4318, "Blend fragments back to front"): the
    // over operator oit_over(behind, fragment) puts the fragment in front of what is already
    // composited, so start with the farthest fragment (index ppll_n - 1) and end with the
    // nearest (index 0).
    return c;
}
