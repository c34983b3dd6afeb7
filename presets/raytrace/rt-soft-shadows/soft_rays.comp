#version 450
// rt-soft-shadows: one shadow ray per pixel per frame towards a point of the sun's disc
// (sun_disc.glsl), accumulated over frames "like TAA" (000_c9f7e5de708ecbb3.txt L5771-5775):
//     v_k = visibility of sample k,   mean_k = mean_{k-1} + (v_k - mean_{k-1}) / (k + 1)
// k = frame.accum_frame, the frames since the camera, view size or a param last changed (0 then:
// the history restarts). Writes the running mean into `accum` (r; its history `accum_prev` is
// last frame's), the picture `ldr` and the shadow family's `vis` target (r = the mean).
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/shadow_scene.glsl"
#include "sun_disc.glsl"
uniform sampler2D gpos;
uniform sampler2D gnrm;
uniform sampler2D accum_prev;
layout(rgba32f) writeonly uniform image2D accum;
layout(rgba8) writeonly uniform image2D ldr;
layout(rgba16f) writeonly uniform image2D vis;

void main() {
    ivec2 px = ivec2(rt_launch_index());
    if (any(greaterThanEqual(px, imageSize(vis)))) return;
    vec3 p, n;
    int object;
    float v = 1.0;
    vec3 l = vec3(0.0, 1.0, 0.0);
    int k = frame.accum_frame;
    if (shadow_scene_surface(gpos, gnrm, px, p, n, object)) {
        l = shadow_light_dir(p);
        v = shadow_scene_visibility(p, n, sun_disc_direction(l, radians(params.sun_deg), sun_disc_sample(px, k)));
    }
    float mean = k == 0 ? v : mix(texelFetch(accum_prev, px, 0).r, v, 1.0 / float(k + 1));
    imageStore(accum, px, vec4(mean, 0.0, 0.0, 1.0));
    imageStore(ldr, px, shadow_scene_shade(object, n, l, mean));
    imageStore(vis, px, shadow_scene_vis(object, n, l, mean));
}
