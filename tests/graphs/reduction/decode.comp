#version 450
// The four atomic words back to floats: (min, max, masked min, masked max).
layout(local_size_x = 1) in;
layout(std430) readonly buffer Range { uint w[4]; } range;
layout(std430) writeonly buffer MinMax { float v[4]; } minmax;
void main() {
    minmax.v[0] = uintBitsToFloat(~range.w[0]);
    minmax.v[1] = uintBitsToFloat(range.w[1]);
    minmax.v[2] = uintBitsToFloat(~range.w[2]);
    minmax.v[3] = uintBitsToFloat(range.w[3]);
}
