#version 450
// Tests: the billboards again, each fragment inside the billboard's inscribed disc counted for
// its instance: sum of pixel x, sum of pixel y, count (integer atomics: exact). The centroid of
// the covered pixel centres is where the rasteriser really put the flare.
layout(location = 0) in vec2 v_local;
layout(location = 1) flat in int v_flare;
layout(location = 0) out vec4 unused;
layout(std430) buffer centroids { uint sums[]; };
void main() {
    if (dot(v_local, v_local) > 1.0) discard;
    ivec2 p = ivec2(gl_FragCoord.xy);
    atomicAdd(sums[3 * v_flare + 0], uint(p.x));
    atomicAdd(sums[3 * v_flare + 1], uint(p.y));
    atomicAdd(sums[3 * v_flare + 2], 1u);
    unused = vec4(1.0);
}
