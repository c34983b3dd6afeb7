// Patch distance for the image-synthesis presets: the sum of squared RGB differences between the
// (2r+1)^2 patch centred at a in image A and the one centred at b in image B
// (003_cfc3b5b225ddab3d.txt L117-125: "overlapping patches, each defined by its centre pixel";
// the NN distance d(a, b), L137-139). Texels of A's patch outside A are left out (a border
// patch is compared on its inside part); b must be a valid centre, its whole patch inside B
// (patch_clamp_centre). `limit` ends the sum early once it exceeds the best distance so far:
// the result is then some value > limit, which a caller comparing `d < best` treats the same.
#ifndef PASSLAB_IMAGE_PATCH_GLSL
#define PASSLAB_IMAGE_PATCH_GLSL

ivec2 patch_clamp_centre(ivec2 b, ivec2 size_b, int r) {
    return clamp(b, ivec2(r), size_b - 1 - r);
}

float patch_ssd(sampler2D A, ivec2 a, sampler2D B, ivec2 b, int r, float limit) {
    ivec2 size_a = textureSize(A, 0);
    float sum = 0.0;
    for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
            ivec2 pa = a + ivec2(dx, dy);
            if (any(lessThan(pa, ivec2(0))) || any(greaterThanEqual(pa, size_a))) continue;
            vec3 e = texelFetch(A, pa, 0).rgb - texelFetch(B, b + ivec2(dx, dy), 0).rgb;
            sum += dot(e, e);
        }
        if (sum > limit) return sum;   // already worse: the rows left cannot make it better
    }
    return sum;
}
#endif
