#version 450
// Tests (fp32): the half-resolution composite of composite.glsl, checked against its two
// inputs, each fetched here independently of the mix:
//   x = in focus (blur <= 1 px): max |composite - sharp input| (must be 0 exactly:
//       mix(a, b, 0) = a), else 0;
//   y = blurred (blur >= 2 px): max |composite - upsampled gather| (0 exactly:
//       mix(a, b, 1) = b), else 0;
//   z = 1 where in focus, w = 1 where blurred (the tests ask for both kinds of pixel to exist).
// blur = the bilinear blur the composite reads (the gather's resolution, upsampled).
#include "composite.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 composite_err;
uniform sampler2D color;
uniform sampler2D result;
uniform sampler2D blur;
float maxc(vec3 v) { return max(v.x, max(v.y, v.z)); }
void main() {
    vec3 c = dof_composite(color, result, blur, uv).rgb;
    vec3 sharp = textureLod(color, uv, 0.0).rgb, gathered = texture(result, uv).rgb;
    float b = texture(blur, uv).x;
    // The promise as stated (README, params doc), not composite.glsl's constant: a changed
    // kSharpBelow is a changed promise and fails here.
    const float kInFocusPx = 1.0, kBlurredPx = 2.0;
    bool in_focus = b <= kInFocusPx, blurred = b >= kBlurredPx;
    composite_err = vec4(in_focus ? maxc(abs(c - sharp)) : 0.0, blurred ? maxc(abs(c - gathered)) : 0.0,
                         in_focus ? 1.0 : 0.0, blurred ? 1.0 : 0.0);
}
