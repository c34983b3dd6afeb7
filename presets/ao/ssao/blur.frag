#version 450
// 4x4 box blur (003 L343: "blur the occlusion map to reduce noise"): exactly one period of the
// 4x4 rotation pattern, so every output pixel averages all 16 kernel rotations. Offsets -2..1
// keep the box's weights summing to 1; at the borders it clamps.
// The 16 texels come four at a time from textureGather: a gather at the corner shared by
// texels (i, j) and (i + 1, j + 1) returns that 2x2 block, and its clamp addressing repeats the
// border texels exactly as clamping the offsets would (4 fetches instead of 16).
layout(location = 0) in vec2 uv;
layout(location = 0) out float ao;
uniform sampler2D ao_raw;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (!params.blur) {
        ao = texelFetch(ao_raw, px, 0).r;
        return;
    }
    // The corners between offsets -2|-1 and 0|1 in texel units: px - 1 and px + 1.
    vec2 lo = (vec2(px) - 1.0) * frame.resolution.zw, hi = (vec2(px) + 1.0) * frame.resolution.zw;
    vec4 s = textureGather(ao_raw, lo, 0) + textureGather(ao_raw, vec2(hi.x, lo.y), 0)
           + textureGather(ao_raw, vec2(lo.x, hi.y), 0) + textureGather(ao_raw, hi, 0);
    ao = (s.x + s.y + s.z + s.w) / 16.0;
}
