#version 450
// Ray-traced reference visibility of the shared scene's ground (test-only pass): from each ground
// pixel's world point a shadow ray towards the light against the casters' triangles
// ("trace a ray from P to the light; if it hits an object first, P is in shadow",
// 003_cfc3b5b225ddab3d.txt L242-246). Output `ref`:
//     r = reference visibility (1 lit, 0 shadowed; 1 off the ground),
//     g = 1 on ground pixels outside the edge band (where a method must agree),
//     b = 1 inside the band: a shadow edge lies within SHADOW_BAND (world units, defined by the
//         pass, e.g. 2 map texels) of the point, found by 8 rays shifted by SHADOW_BAND across
//         the light direction disagreeing with the centre ray.
// The graph declares the casters' BVH, `generator = "bvh", meshes = ["box", "ball"]` (mesh 0 the
// box, mesh 1 the ball), bound as `scene`, and binds `world` (shade.frag's target 2).
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/bvh.glsl"
#include "shadows/scene.glsl"
#include "shadows/light.glsl"
uniform sampler2D world;
layout(rgba16f) uniform writeonly image2D ref;

// A point light ends the shadow ray: casters beyond it do not shadow o.
float shadow_ray_tmax(vec3 o) {
#ifdef SHADOW_POINT_LIGHT
    return distance(o, SHADOW_POINT_LIGHT);
#else
    return 1e30;
#endif
}

bool shadow_ray_occluded(vec3 o, vec3 l) {
    // Mesh k of the BVH is object k + 1 of scene.glsl. tmin: a ground point does not hit the
    // box's base, which lies in the ground's plane.
    for (int k = 0; k < 2; ++k)
        if (pl_bvh_occluded(uint(k), inverse(shadow_model(k + 1)), o, l, 1e-4, shadow_ray_tmax(o))) return true;
    return false;
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, imageSize(ref)))) return;
    vec4 w = texelFetch(world, px, 0);
    if (int(w.w + 0.5) != SHADOW_GROUND + 1) {
        imageStore(ref, px, vec4(1.0, 0.0, 0.0, 1.0));
        return;
    }
    vec3 p = w.xyz, l = shadow_light_dir(p);
    bool centre = shadow_ray_occluded(p, l);
    vec3 u = normalize(abs(l.y) < 0.99 ? cross(l, vec3(0, 1, 0)) : cross(l, vec3(1, 0, 0)));
    vec3 v = cross(l, u);
    bool band = false;
    for (int k = 0; k < 8 && !band; ++k) {
        float a = 0.785398163 * float(k);
        band = shadow_ray_occluded(p + SHADOW_BAND * (cos(a) * u + sin(a) * v), l) != centre;
    }
    imageStore(ref, px, vec4(centre ? 0.0 : 1.0, band ? 0.0 : 1.0, band ? 1.0 : 0.0, 1.0));
}
