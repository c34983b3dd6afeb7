#version 450
// The offset map (h, h_u, h_v) of the selected height field, for the one prism pass.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 offsets;
// h alone (the same float): the march samples it up to 23 times per fragment, and a one-channel
// texture filters a quarter of the channels (lavapipe filters each channel in software).
layout(location = 1) out float height_map;
uniform sampler2D off_tiles;
uniform sampler2D off_zero;
uniform sampler2D off_top;
uniform sampler2D off_ramp;
void main() {
    offsets = params.heights == HEIGHTS_ZERO ? texture(off_zero, uv) : params.heights == HEIGHTS_TOP ? texture(off_top, uv) : params.heights == HEIGHTS_RAMP ? texture(off_ramp, uv) : texelFetch(off_tiles, ivec2(gl_FragCoord.xy), 0);
    height_map = offsets.x;
}
