// Marching the voxel grid: a shadow ray through the marked cells, and a cone through the
// radiance mip chain (voxel cone tracing: each step samples the level whose cells are as wide as
// the cone there, so one lookup stands for the whole cross-section).
#ifndef PASSLAB_GI_VOXEL_CONE_GLSL
#define PASSLAB_GI_VOXEL_CONE_GLSL

#include "gi/voxel_grid.glsl"
#include "common/sampling.glsl"

// The voxelisation: per cell 0 (empty) or the id of the surface in it (voxelize.comp).
layout(r32ui) readonly uniform uimage3D voxels;

// 1 if the segment a -> b crosses no marked cell (half-cell steps; b's own cell not tested).
float voxel_visible(vec3 a, vec3 b) {
    vec3 d = b - a;
    float len = length(d);
    int steps = int(len / (0.5 * VX_SIZE));
    ivec3 target = voxel_of(b);
    for (int i = 0; i < steps; ++i) {
        ivec3 c = voxel_of(a + d * (float(i) / float(steps)));
        if (c == target) break;
        if (imageLoad(voxels, c).r != 0u) return 0.0;
    }
    return 1.0;
}

#ifdef VX_CONES
// The injected radiance with its mip chain (inject.comp, downsample.comp).
uniform sampler3D radiance;

// Front-to-back along a cone of half-angle tan = tan_half from x in direction d: returns the
// radiance it gathers (premultiplied levels: c += (1 - a) s.rgb, a += (1 - a) s.a).
vec3 voxel_cone(vec3 x, vec3 d, float tan_half) {
    vec3 c = vec3(0.0);
    float a = 0.0, dist = VX_SIZE;
    while (dist < 2.8 && a < 0.95) {
        float diameter = max(VX_SIZE, 2.0 * tan_half * dist);
        vec3 p = x + d * dist;
        if (any(greaterThan(abs(p), vec3(VX_EXTENT)))) break;
        float lod = log2(diameter / VX_SIZE);
        vec4 s = textureLod(radiance, voxel_uvw(p), lod);
        // A surface is one cell thick: at level lod it fills only 1 / 2^lod of a cell's volume
        // though it blocks the whole cross-section, so coverage (and the premultiplied radiance
        // with it) is scaled back up by 2^lod, at most to opaque.
        s *= min(exp2(lod), 1.0 / max(s.a, 1e-4));
        c += (1.0 - a) * s.rgb;
        a += (1.0 - a) * s.a;
        dist += 0.5 * diameter;
    }
    return c;
}

// The mean incoming radiance over the hemisphere around n, cosine-weighted, by 6 cones of
// 60 degrees: one along n (weight 0.25), five at 60 degrees from it (0.15 each); sum 1.
vec3 voxel_hemisphere(vec3 o, vec3 n) {
    const float tan30 = 0.577350;  // 60-degree cones: half-angle 30 degrees
    mat3 b = basis_from_normal(n);
    vec3 l = 0.25 * voxel_cone(o, n, tan30);
    for (int k = 0; k < 5; ++k) {
        float phi = 6.28318530718 * float(k) / 5.0;
        l += 0.15 * voxel_cone(o, b * vec3(0.866025 * cos(phi), 0.866025 * sin(phi), 0.5), tan30);
    }
    return l;
}
#endif

#endif
