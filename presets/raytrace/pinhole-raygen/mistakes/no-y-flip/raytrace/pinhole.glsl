// MISTAKE no-y-flip: the exercise solved with ndc = 2 c - 1 on both axes (the texture-lookup habit).
// EXERCISE — this file shadows passes/raytrace/pinhole.glsl for raytrace/pinhole-raygen.
//     passlab run   presets/raytrace/pinhole-raygen --exercise presets/raytrace/pinhole-raygen/exercise
//     passlab grade presets/raytrace/pinhole-raygen --exercise presets/raytrace/pinhole-raygen/exercise
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
    // TODO 1: the pixel centre and its normalized device coordinate (000_c9f7e5de708ecbb3.txt
    // L5623-5624): c = (pix + 0.5) / dims in [0, 1]^2, then ndc = (2, -2) * c + (-1, 1): x from
    // -1 (left) to 1, y from +1 on row 0 (the top) to -1 (the bottom row) -- the y flip.
    vec2 centre = (vec2(pix) + vec2(0.5)) / vec2(dims);
    vec2 ndc = 2.0 * centre - 1.0;
    // TODO 2: the pixel's ray direction (L5625, L5628): dir = ndc.x * U + ndc.y * V + W through
    // the image plane at distance 1 (the listing writes wsCamZ; the block declares wsCamW),
    // normalised so that t is a distance. As shipped every ray goes straight ahead.
    vec3 dir = normalize(ndc.x * cam.u + ndc.y * cam.v + cam.w);
    return RtRay(cam.pos, 0.0, normalize(dir), 999999999.0);
}

#endif
