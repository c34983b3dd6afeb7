#version 450
// rt-hard-shadows: the ray generation stage, one shadow ray per pixel from the G-buffer's surface
// point towards the sun through the BVH of the shared shadow scene (raytrace/shadow_scene.glsl,
// the ray raytrace/shadow_ray.glsl): miss = lit, any hit = shadowed. Writes the picture `ldr` and
// the shadow family's visibility target `vis` (shadow_scene_vis).
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/shadow_scene.glsl"
uniform sampler2D gpos;
uniform sampler2D gnrm;
layout(rgba8) writeonly uniform image2D ldr;
layout(rgba16f) writeonly uniform image2D vis;

void main() {
    ivec2 px = ivec2(rt_launch_index());
    if (any(greaterThanEqual(px, imageSize(vis)))) return;
    vec3 p, n;
    int object;
    float v = 1.0;
    vec3 l = vec3(0.0, 1.0, 0.0);
    if (shadow_scene_surface(gpos, gnrm, px, p, n, object)) {
        l = shadow_light_dir(p);
        v = shadow_scene_visibility(p, n, l);
    }
    imageStore(ldr, px, shadow_scene_shade(object, n, l, v));
    imageStore(vis, px, shadow_scene_vis(object, n, l, v));
}
