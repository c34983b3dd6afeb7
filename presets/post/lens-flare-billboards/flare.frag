#version 450
// The billboard's colour and coverage, alpha-blended over the image (000 L3682: "transparent
// billboards (alpha blending)"): dst = a c + (1 - a) dst.
#include "flares.glsl"
layout(location = 0) in vec2 v_local;
layout(location = 1) flat in int v_flare;
layout(location = 0) out vec4 hdr;
void main() {
    float a = kAlpha[v_flare] * params.strength * flare_visibility(params.light) * flare_shape(kShape[v_flare], v_local);
    hdr = vec4(kTint[v_flare] * params.flare_radiance, clamp(a, 0.0, 1.0));
}
