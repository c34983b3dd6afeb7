// The gather the shared low-res passes call (gi/rsm_lowres.comp, gi/rsm_compose.frag): the VPLs
// and their shadow maps, passes/gi/vpl_gather.glsl, unchanged from instant-radiosity; the passes
// bind its `vpl_maps` to the imperfect shadow maps (ism_pull, level 0) or, for the tests, to the
// triangle maps (tri_maps).
#include "gi/vpl_gather.glsl"
