#version 450
// EXERCISE: continuous motion blur by line sampling (000_c9f7e5de708ecbb3.txt L3608-3613): "for
// each pixel compute how the pixel moves over time, sample a line along that direction,
// accumulate colour". vel_max holds the (dilated) velocity in pixels per frame, which you compute
// in motion/velocity.glsl (TODO 1). Fill in TODO 2 and TODO 3; taps are rounded to whole texels
// (texelFetch) so a tap count is exact, as the tests count them.
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
    // TODO 2: the blur line. The shutter is open for a fraction s = params.shutter of the frame
    // (000 L3608-3613: the blur is the motion during the exposure), so the line the pixel saw
    // is s times the motion per frame: v_blur = s v, with v = texelFetch(vel_max, px, 0).xy.
    vec2 v = vec2(0.0);  // replace: the velocity scaled to the exposure
    int n = max(params.samples, 1);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < n; ++i) {
        // TODO 3: the tap positions. N = n taps spread evenly over the line, k_i from k0 to
        // k0 + 1 (i = 0 .. N-1), with k0 = -1/2 when params.centred (the document's fix for
        // "blur not centred", L3638-3642: the line is centred on the pixel) and k0 = 0 when
        // trailing; a single tap (N = 1) is the pixel itself. The tap reads the current frame at
        //   q = p + round(k_i v)   (clamped to the image),
        // and C(p) = 1/N sum_i C_now(q_i).
        ivec2 q = px;  // replace
        sum += texelFetch(color, q, 0).rgb;
    }
    blurred = vec4(sum / float(n), 1.0);
    ldr = as_shown(blurred.rgb);
}
