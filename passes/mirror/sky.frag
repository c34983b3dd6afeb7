#version 450
// The sky behind everything (envmap/sky.glsl), in the world direction of each pixel.
//   INV_VIEW_PROJ  the camera's inverse (default the view's; the mirrored camera's for RTT)
//   EYE            its position
//   REFLECTED      1: the sky as the mirror shows it: the direction reflected by the plane
//                  (the stencil method's reflected background, drawn only where stencil = 1)
//   ALPHA          optional expression for the alpha channel (default 1)
//   MASK_TARGET    optional second target: 1 wherever this pass wrote (the leak test)
#include "mirror/mirror.glsl"
#include "mirror/scene.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
#ifdef MASK_TARGET
layout(location = 1) out vec4 MASK_TARGET;
#endif
#ifndef INV_VIEW_PROJ
#define INV_VIEW_PROJ frame.inv_view_proj
#endif
#ifndef EYE
#define EYE frame.camera_pos.xyz
#endif
#ifndef REFLECTED
#define REFLECTED 0
#endif
#ifndef VISIBLE
#define VISIBLE true
#endif
void main() {
    if (!(VISIBLE)) discard;
    vec4 w = (INV_VIEW_PROJ) * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    vec3 d = normalize(w.xyz / w.w - (EYE));
#if REFLECTED
    d = mirror_direction(d);
#endif
#ifndef ALPHA
#define ALPHA 1.0
#endif
    hdr = vec4(sky_color(d), ALPHA);
#ifdef MASK_TARGET
    MASK_TARGET = vec4(1.0);
#endif
}
