// Counting, on the GPU, the triangles that were rasterised: a fragment sets its triangle's flag
// (atomicExchange) and the first fragment of each triangle counts it. The fragment shader must not
// declare early_fragment_tests, so it runs before the depth test and a triangle counts even where
// it is hidden: the count is what the rasteriser produced, not what survived depth. A triangle
// that covers no pixel centre produces no fragment and is not counted (in any mode alike).
//
// Bind a buffer `raster` of 4 + 4 * triangles bytes, cleared to 0 every frame:
//   raster.count = triangles that produced a fragment, raster.seen[t] = 1 for each of them.
#ifndef PASSLAB_RASTER_COUNT_GLSL
#define PASSLAB_RASTER_COUNT_GLSL
layout(std430) buffer Raster { uint count; uint seen[]; } raster;

// `triangle` = a global index: instance * triangles per instance + gl_PrimitiveID.
void pl_count_rasterised(uint triangle) {
    if (atomicExchange(raster.seen[triangle], 1u) == 0u) atomicAdd(raster.count, 1u);
}
#endif
