#version 450
// Continuous motion blur by line sampling (000_c9f7e5de708ecbb3.txt L3608-3613): "for each
// pixel compute how the pixel moves over time, sample a line along that direction, accumulate
// colour". With exposure s (params.shutter) a pixel p saw what the current frame shows at
//   p + k s v,   k in [-1/2, 1/2] (centred, 000 L3638-3642) or k in [0, 1] (trailing),
// averaged over N taps. Taps are rounded to whole texels (texelFetch) so a tap count is exact.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 blurred;
layout(location = 1) out vec4 ldr;  // the view (show = result); display.frag draws the others
uniform sampler2D color;
uniform sampler2D vel_max;

// The view's pixel, as display.frag showed it when it was a pass of its own (speed: one pass
// less): the rgba16f value `blurred` stores, clamped. lavapipe rounds to half toward zero (the
// 13 low mantissa bits dropped; values below half's normal range encode to 0 in 8 bits anyway),
// so the view is bit for bit the former one there; a device that rounds to nearest differs by
// at most 1/255 in rare pixels.
vec4 as_shown(vec3 c) {
    vec3 h = uintBitsToFloat(floatBitsToUint(c) & 0xFFFFE000u);
    return vec4(clamp(h, 0.0, 1.0), 1.0);
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy), size = ivec2(frame.resolution.xy);
    vec2 v = texelFetch(vel_max, px, 0).xy * params.shutter;
    int n = max(params.samples, 1);
    float k0 = params.centred ? -0.5 : 0.0;
    vec3 sum = vec3(0.0);
    for (int i = 0; i < n; ++i) {
        float k = n > 1 ? k0 + float(i) / float(n - 1) : 0.0;  // one tap: the pixel itself
        ivec2 q = clamp(px + ivec2(round(k * v)), ivec2(0), size - 1);
        sum += texelFetch(color, q, 0).rgb;
    }
    blurred = vec4(sum / float(n), 1.0);
    ldr = as_shown(blurred.rgb);
}
