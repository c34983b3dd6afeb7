// 32-bit atomic loop k-buffer (002_644d46bdce7e5305.txt L1568-1648; the hybrid's oitPassOne and
// oitPassTwo, L1707-1782). Each pixel owns params.k depth slots, cleared to 0xffffffff every frame
// (the buffer's `clear`; the listing's oitClear, L1696-1701, does it in a shader). Shared by
// atomic-loop-kbuffer and hybrid-atomic-wboit.
//
// Depths are compared as uint bit patterns: for z in [0, 1] (non-negative floats) the IEEE bits
// order like the floats, so atomicMin on uints keeps the nearest. Pitfall, stated both ways: the
// listing writes `uint lFragDepth = floatBitsToInt(gl_FragCoord.z);` in pass one (L1590, L1710)
// and in the hybrid's pass two (L1725), but floatBitsToUint in the k-buffer's pass two (L1627).
// GLSL converts the int to uint implicitly with the same bits, so both agree for z >= 0; only a
// negative depth (reversed or unclamped z) would order wrongly, and then in both. We use
// floatBitsToUint throughout.
layout(std430) coherent buffer KDepth { uint slot[]; } kdepth;

int oit_kbuffer_base() {
    return (int(gl_FragCoord.y) * int(frame.target.x) + int(gl_FragCoord.x)) * params.k;
}

// Pass one (L1590-1602): insert this fragment's depth into the pixel's ascending list of the k
// nearest depths. atomicMin puts the smaller of (slot, d) in the slot and hands back the old
// value; the larger one travels on to the next slot. An empty slot (0xffffffff) or an equal depth
// ends the walk: equal depths share one slot (the listing's behaviour; their colours race in pass
// two). A depth farther than all k falls off the end: pass two sends it to the tail.
void oit_kbuffer_insert() {
    uint d = floatBitsToUint(gl_FragCoord.z);
    int base = oit_kbuffer_base();
    // L1596-1602: old = atomicMin(slot, d); stop at 0xffffffff or old == d; d = max(old, d)
    for (int i = 0; i < params.k; ++i) {
        uint old = atomicMin(kdepth.slot[base + i], d);
        if (old == 0xffffffffu || old == d) break;
        d = max(old, d);
    }
}

// Pass two (L1627-1647): the slot holding this fragment's depth, by binary search of the
// ascending list, or -1 when it was not kept (it lies behind the k nearest: the tail).
// The listing's loop is `while (lLow < lHigh)` with `lHigh = lMiddle - 1` (L1631-1638; the
// hybrid's, L1731-1737): it never tests the element where lLow meets lHigh, so it misses the slot
// it ends on (with k = 1 it never runs at all and every fragment goes to the tail; with k = 4 the
// farthest kept depth is never found). Corrected here to `while (lo <= hi)`.
int oit_kbuffer_find() {
    uint d = floatBitsToUint(gl_FragCoord.z);
    int base = oit_kbuffer_base();
    // binary search for d in slot[base .. base + k - 1] (ascending)
    int lo = 0, hi = params.k - 1;
    while (lo <= hi) {
        int mid = lo + ((hi - lo) >> 1);
        uint t = kdepth.slot[base + mid];
        if (d > t) lo = mid + 1;
        else if (d < t) hi = mid - 1;
        else return mid;
    }
    return -1;
}
