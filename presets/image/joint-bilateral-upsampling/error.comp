#version 450
// Over the edge band: the RMSE of the joint bilateral and of the bilinear upsampling against the
// full-resolution reference, and their ratio: stats = { ratio, rmse_jbu, rmse_bilinear, pixels }.
// One work group, a fixed order of additions.
layout(local_size_x = 256) in;
uniform sampler2D upsampled;
uniform sampler2D bilinear;
uniform sampler2D truth;
uniform sampler2D edges;
layout(std430) buffer Stats { float value[]; } stats;

shared vec3 partial[256];

void main() {
    ivec2 size = textureSize(truth, 0);
    uint t = gl_LocalInvocationIndex;
    vec3 s = vec3(0.0);   // x: jbu squared error, y: bilinear squared error, z: pixels
    for (int i = int(t); i < size.x * size.y; i += 256) {
        ivec2 p = ivec2(i % size.x, i / size.x);
        if (texelFetch(edges, p, 0).r == 0.0) continue;
        vec3 ref = texelFetch(truth, p, 0).rgb;
        vec3 a = texelFetch(upsampled, p, 0).rgb - ref, b = texelFetch(bilinear, p, 0).rgb - ref;
        s += vec3(dot(a, a), dot(b, b), 1.0);
    }
    partial[t] = s;
    barrier();
    for (uint k = 128u; k > 0u; k >>= 1) {
        if (t < k) partial[t] += partial[t + k];
        barrier();
    }
    if (t == 0u) {
        vec3 v = partial[0];
        float rj = sqrt(v.x / max(3.0 * v.z, 1.0)), rb = sqrt(v.y / max(3.0 * v.z, 1.0));
        stats.value[0] = rb > 0.0 ? rj / rb : 0.0;
        stats.value[1] = rj;
        stats.value[2] = rb;
        stats.value[3] = v.z;
    }
}
