// The gather the shared low-res passes call (gi/rsm_lowres.comp, gi/rsm_compose.frag): the VPLs
// and their shadow maps, passes/gi/vpl_gather.glsl (the exercise's file).
#include "gi/vpl_gather.glsl"
