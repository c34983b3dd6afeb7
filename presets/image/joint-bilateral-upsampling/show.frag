#version 450
// The view: bilinear left of the split line, joint bilateral right of it (the ring and the
// box's edges show the difference), or the low-resolution colour itself (nearest).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D low_color;
uniform sampler2D bilinear;
uniform sampler2D upsampled;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (params.show == SHOW_LOW) {
        color = texelFetch(low_color, p * textureSize(low_color, 0) / textureSize(upsampled, 0), 0);
        return;
    }
    bool left = params.show == SHOW_BILINEAR || (params.show == SHOW_SPLIT && uv.x < params.split);
    color = vec4(left ? texelFetch(bilinear, p, 0).rgb : texelFetch(upsampled, p, 0).rgb, 1.0);
    if (params.show == SHOW_SPLIT && abs(uv.x - params.split) * frame.resolution.x < 1.0) color = vec4(1.0);
}
