// Per-object light lists (003_cfc3b5b225ddab3d.txt L683-700: "each scene object maintains a
// list of lights that illuminate it ... by intersecting light volumes with scene geometry,
// per light-object pair, not light-fragment pair"). Object 0 is the floor, 1 + i ball i.
// Buffer layout (lists.comp writes, the draws read):
//   object_lights: per object kListWords words: [count, light 0, light 1, ..., padding]
//   object_masks:  per object 2 words: bit i of word i / 32 set when light i is listed
#ifndef FORWARD_OBJECT_LISTS_GLSL
#define FORWARD_OBJECT_LISTS_GLSL
const int kObjects = 65, kMaxLights = 64, kListWords = kMaxLights + 1;
const uint kNoLight = 0xffffffffu;  // pads a list to its batch size

// The smallest specialised shader that holds n lights: 4, 8, 16, 32 or 64.
int batch_of(uint n) { return n <= 4u ? 4 : n <= 8u ? 8 : n <= 16u ? 16 : n <= 32u ? 32 : 64; }
#endif
