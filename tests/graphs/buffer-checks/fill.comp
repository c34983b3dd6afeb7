#version 450
// Writes known values for the buffer checks: 16 words of every decoding (0xffffffff, negative
// ints, floats), 8 structs { uint id; int delta; float value; uint flags }, and 64 groups of 16
// { key, payload } records, each group sorted by key (insertion sort, one thread per group).
layout(local_size_x = 64) in;

struct Item { uint id; int delta; float value; uint flags; };
struct Rec { uint key; uint payload; };

layout(std430) writeonly buffer Words { uint w[16]; } words;
layout(std430) writeonly buffer Structs { Item item[8]; } structs;
layout(std430) buffer Keys { Rec rec[]; } keys;

// A small integer hash (Wang): deterministic, unordered keys.
uint hash(uint x) {
    x = (x ^ 61u) ^ (x >> 16);
    x *= 9u;
    x ^= x >> 4;
    x *= 0x27d4eb2du;
    return x ^ (x >> 15);
}

void main() {
    uint g = gl_LocalInvocationID.x;
    if (g == 0u) {
        words.w[0] = 0xffffffffu;
        words.w[1] = 7u;
        words.w[2] = uint(-5);
        words.w[3] = floatBitsToUint(1.5);
        words.w[4] = floatBitsToUint(-0.25);
        words.w[5] = uint(-2147483648);
        for (uint i = 6u; i < 16u; ++i) words.w[i] = i * i;  // 36, 49, ... 225: sum 1185
    }
    if (g < 8u) structs.item[g] = Item(g, -int(g), float(g) * 0.5, 0xf0000000u | g);
    Rec r[16];
    for (uint j = 0u; j < 16u; ++j) r[j] = Rec(hash(g * 16u + j) % 1000u, g * 16u + j);
    for (int i = 1; i < 16; ++i) {
#ifdef BREAK_SORT
        break;  // deliberate break: leave the groups unsorted
#endif
        Rec x = r[i];
        int j = i - 1;
        while (j >= 0 && r[j].key > x.key) {
            r[j + 1] = r[j];
            --j;
        }
        r[j + 1] = x;
    }
    for (uint j = 0u; j < 16u; ++j) keys.rec[g * 16u + j] = r[j];
}
