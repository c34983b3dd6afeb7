// The pinhole camera's ray generation (000_c9f7e5de708ecbb3.txt L5618-5652): the raygen data
// block of L5589-5594 (wsCamPos and the right/up/forward vectors wsCamU, wsCamV, wsCamW) and the
// pixel's primary ray. Needs raytrace/stages.glsl (RtRay).
//
// The listing's typos, fixed here: it adds `wsCamZ` (L5628) but declares `wsCamW` (L5593).
#ifndef PASSLAB_RAYTRACE_PINHOLE_GLSL
#define PASSLAB_RAYTRACE_PINHOLE_GLSL

// The cbuffer RayGenData of L5589-5594, from the view camera: U and V are the right and up
// vectors scaled to the image plane's half width and half height at distance 1 from the eye
// (|U| = aspect tan(fov/2), |V| = tan(fov/2): proj[0][0] and |proj[1][1]| are their inverses),
// W the unit forward vector. frame.inv_view's columns are the camera's axes in world space.
struct RtPinhole {
    vec3 pos, u, v, w;
};

RtPinhole rt_pinhole_camera() {
    return RtPinhole(frame.camera_pos.xyz, frame.inv_view[0].xyz / frame.proj[0][0],
                     frame.inv_view[1].xyz / abs(frame.proj[1][1]), -frame.inv_view[2].xyz);
}

// The primary ray through the centre of pixel `pix` of a `dims` image, row 0 at the top.
RtRay rt_pinhole_ray(RtPinhole cam, uvec2 pix, uvec2 dims) {
    // Pixel centre in [0, 1]^2 (L5623), then NDC as in raster (L5624): x from -1 (left) to 1,
    // y from 1 (top row) to -1 (bottom row): the y flip, because image rows grow downwards.
    vec2 centre = (vec2(pix) + vec2(0.5)) / vec2(dims);
    vec2 ndc = vec2(2.0, -2.0) * centre + vec2(-1.0, 1.0);
    // NDC to the pixel's direction through the image plane at distance 1 (L5625), unit length
    // (L5628) so that t is a distance. TMin 0, TMax 999999999 as the listing (L5629-5630).
    vec3 dir = ndc.x * cam.u + ndc.y * cam.v + cam.w;
    return RtRay(cam.pos, 0.0, normalize(dir), 999999999.0);
}

#endif
