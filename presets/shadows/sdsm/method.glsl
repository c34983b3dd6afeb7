// sdsm: the cascade lookup of passes/shadows/cascade_lookup.glsl (shared with
// cascaded-shadow-maps); what differs is where the cascades come from (sdsm_reduce.comp):
// 000_c9f7e5de708ecbb3.txt L4709-4719.
#include "shadows/cascade_lookup.glsl"
