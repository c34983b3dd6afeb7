// cascaded-shadow-maps: the lookup is passes/shadows/cascade_lookup.glsl (shared with sdsm):
// 000_c9f7e5de708ecbb3.txt L4709-4719.
#include "shadows/cascade_lookup.glsl"
