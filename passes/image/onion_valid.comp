#version 450
// The candidate centres: r = 1 where the whole N x N window lies inside the picture and outside
// the hole, so every texel a candidate patch is compared on (and its centre, which is copied)
// is a known one (L65-79: the fill copies from the rest of the picture).
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D hole;
layout(rgba8) uniform writeonly image2D valid;

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(valid);
    if (any(greaterThanEqual(q, size))) return;
    int h = params.half_window;
    bool ok = all(greaterThanEqual(q, ivec2(h))) && all(lessThan(q, size - h));
    for (int dy = -h; dy <= h && ok; ++dy)
        for (int dx = -h; dx <= h && ok; ++dx)
            ok = texelFetch(hole, q + ivec2(dx, dy), 0).r == 0.0;
    imageStore(valid, q, vec4(ok ? 1.0 : 0.0, 0.0, 0.0, 1.0));
}
