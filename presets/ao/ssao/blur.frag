#version 450
// 4x4 box blur (003 L343: "blur the occlusion map to reduce noise"): exactly one period of the
// 4x4 rotation pattern, so every output pixel averages all 16 kernel rotations. Offsets -2..1
// keep the box's weights summing to 1; at the borders it clamps.
layout(location = 0) in vec2 uv;
layout(location = 0) out float ao;
uniform sampler2D ao_raw;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy), last = ivec2(frame.resolution.xy) - 1;
    if (!params.blur) {
        ao = texelFetch(ao_raw, px, 0).r;
        return;
    }
    float sum = 0.0;
    for (int y = -2; y < 2; ++y)
        for (int x = -2; x < 2; ++x) sum += texelFetch(ao_raw, clamp(px + ivec2(x, y), ivec2(0), last), 0).r;
    ao = sum / 16.0;
}
