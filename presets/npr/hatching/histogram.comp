#version 450
// Tone calibration, step 1 (bake = true): how many texels of the tile each stroke is the first
// to cover (stroke_histogram is cleared by the baked pass before this one).
layout(local_size_x = 16, local_size_y = 16) in;
uniform sampler2D stroke_index;
layout(r32ui) uniform uimage2D stroke_histogram;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, textureSize(stroke_index, 0)))) return;
    imageAtomicAdd(stroke_histogram, ivec2(int(texelFetch(stroke_index, p, 0).r), 0), 1u);
}
