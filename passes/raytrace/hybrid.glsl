// Hybrid reflections (000_c9f7e5de708ecbb3.txt L5753-5763, L5789-5800): the rasterised frame and
// screen-space reflections first; rays through the host BVH only where SSR found nothing (its
// gaps: off screen, behind objects, beyond its steps); the environment map where the ray also
// escapes. "Trace only where necessary" (L5746-5750).
//
// The scene is passes/mirror's (a teapot, a ball, a tilted box over a mirror floor): its model
// matrices place the instances, so the rays see what the rasteriser drew. Hit points are shaded
// with the same function as the raster objects, seen from the mirror point (where a reflection
// is seen from), so the traced reflection is the surface as the mirror shows it, specular
// highlight included; SSR can only re-use the colour the camera saw.
//
// Normals: the BVH buffer reorders triangles, a `triangles` buffer keeps the meshes' index order
// (docs/format.md), so triangle `prim` of mesh m is record m.triangle_offset + prim there. The
// buffers hold positions only: the normal is the triangle's (flat), rotated by the instance;
// the ball's is the sphere's own (flat facets of a 64 x 32 sphere shade up to 0.09 off).
#ifndef PASSLAB_RAYTRACE_HYBRID_GLSL
#define PASSLAB_RAYTRACE_HYBRID_GLSL
#include "raytrace/bvh.glsl"
#include "mirror/scene.glsl"

layout(std430) readonly buffer HybridTriangles {
    PlSceneHeader header;
    uvec4 records[];
} tris;

// Corners of triangle `prim` of mesh `mesh` in the triangles buffer (object space).
void hybrid_triangle(uint mesh, uint prim, out vec3 v0, out vec3 v1, out vec3 v2) {
    uvec4 m = tris.records[tris.header.meshes_at + mesh * PL_SCENE_MESH_RECORDS];
    uint k = tris.header.triangles_at + (m.z + prim) * PL_SCENE_TRIANGLE_RECORDS;
    v0 = uintBitsToFloat(tris.records[k].xyz);
    v1 = uintBitsToFloat(tris.records[k + 1u].xyz);
    v2 = uintBitsToFloat(tris.records[k + 2u].xyz);
}

// The closest object along o + t d (instances 0..kObjects-1 = mesh i, placed by object_model).
PlHit hybrid_closest(vec3 o, vec3 d) {
    PlHit hit = pl_no_hit(1e30);
    for (int i = 0; i < kObjects; ++i) pl_bvh_closest(uint(i), inverse(object_model(i)), i, o, d, 0.0, hit);
    return hit;
}

// The reflection seen along R from the mirror point P: (colour, 1) on a hit, (0, 0) on a miss.
vec4 hybrid_trace_reflection(vec3 P, vec3 N, vec3 R, float specular) {
    vec3 o = P + 1e-3 * N;  // off the mirror, so it never hits itself (it is not in the BVH anyway)
    PlHit hit = hybrid_closest(o, R);
    if (hit.instance < 0) return vec4(0.0);
    vec3 p = o + hit.t * R, n;
    if (hit.instance == 1) {
        // The ball: a sphere generator mesh centred on its origin, whose smooth normal is the
        // direction from the centre (what the rasteriser interpolates from its vertices).
        n = normalize(p - object_model(1)[3].xyz);
    } else {
        vec3 v0, v1, v2;
        hybrid_triangle(hit.mesh, hit.prim, v0, v1, v2);
        n = normalize(mat3(object_model(hit.instance)) * cross(v1 - v0, v2 - v0));
    }
    if (dot(n, R) > 0.0) n = -n;  // face the ray
    return vec4(shade(p, n, P, kAlbedo[hit.instance], specular), 1.0);
}
#endif
