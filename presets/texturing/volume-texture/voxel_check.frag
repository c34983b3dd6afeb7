#version 450
// One pixel per voxel of the 64^3 volume (512 x 512 pixels = 64 x 64 x 64): voxel
// (x % 64, y % 64, (x / 64) + 8 (y / 64)).
//   r: |linear sample at the voxel centre (ijk + 0.5) / N  -  texelFetch(ijk)|   (must be 0)
//   g: |texelFetch(ijk) - phantom(centre)|   (the rgba16f rounding of the baked value)
//   b: the voxel value itself (so the test can see the volume is not constant)
//   a: |linear sample half-way between voxels i and i+1 along x - their mean|
// nearest: max |nearest sample (alias volume_nearest) - texelFetch(ijk)| over the 8 points
//   (ijk + 0.5 +- 0.45) / N inside the voxel (must be 0)
#include "phantom.glsl"
layout(location = 0) out vec4 result;
layout(location = 1) out float nearest;
uniform sampler3D volume;
uniform sampler3D volume_nearest;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    const int n = 64;
    ivec3 ijk = ivec3(px.x % n, px.y % n, px.x / n + 8 * (px.y / n));
    vec3 t = (vec3(ijk) + 0.5) / float(n);
    float sampled = texture(volume, t).r, stored = texelFetch(volume, ijk, 0).r;
    float mid = 0.0;
    if (ijk.x < n - 1) {
        float next = texelFetch(volume, ijk + ivec3(1, 0, 0), 0).r;
        mid = abs(texture(volume, t + vec3(0.5 / float(n), 0.0, 0.0)).r - 0.5 * (stored + next));
    }
    result = vec4(abs(sampled - stored), abs(stored - phantom(voxel_centre(ijk, n))), stored, mid);
    const float kInside = 0.45;   // offset from the centre, in voxels: well inside the voxel
    nearest = 0.0;
    for (int c = 0; c < 8; ++c) {
        vec3 corner = vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1) * 2.0 - 1.0;
        nearest = max(nearest, abs(texture(volume_nearest, t + corner * kInside / float(n)).r - stored));
    }
}
