// Per-pixel linked lists, "Sorting and Blending" (000_c9f7e5de708ecbb3.txt L4316-4319): "Blend
// fragments back to front in PS; must sort by depth value in temp. array". The temporary array
// holds MAX_FRAGS entries (the pitfall: it caps the depth complexity); `cap` = params.max_frags
// <= MAX_FRAGS is how many the resolve keeps: the nearest ones.
// The arrays are private globals, not inout parameters: lavapipe (Mesa 22.3) sorted wrongly on
// some pixels when they were passed inout (measured: a diagonal line of unsorted pixels).
float ppll_z[MAX_FRAGS];   // depths, ascending: ppll_z[0] is the nearest fragment
uint  ppll_c[MAX_FRAGS];   // packUnorm4x8 colours, in the same order
int   ppll_n = 0;          // how many are held

// Insert one fragment (insertion sort, one step per list node). A full array keeps its `cap`
// nearest fragments: a farther one is dropped, a nearer one replaces the farthest.
void ppll_insert(int cap, float z, uint rgba) {
    if (ppll_n < cap) ++ppll_n;
    else if (z >= ppll_z[ppll_n - 1]) return;
    int i = ppll_n - 1;   // append (or overwrite the farthest), then shift it to its place
    for (; i > 0 && ppll_z[i - 1] > z; --i) { ppll_z[i] = ppll_z[i - 1]; ppll_c[i] = ppll_c[i - 1]; }
    ppll_z[i] = z; ppll_c[i] = rgba;
}

// Composite the held fragments over `behind` (the opaque colour): back to front, the farthest
// (index ppll_n - 1) first, each with oit_over (composite.glsl).
vec3 ppll_blend(vec3 behind) {
    vec3 c = behind;
    for (int i = 0; i < ppll_n; ++i) c = oit_over(c, unpackUnorm4x8(ppll_c[i]));
    return c;
}
