#version 450
// The result, or a stage: the flare alone, the thresholded input, or the lens textures.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D final;
uniform sampler2D flare;
uniform sampler2D bright;
uniform sampler2D starburst;
uniform sampler2D dirt;
uniform sampler2D lens_ramp;
void main() {
    vec3 c = params.show == SHOW_FLARE       ? texture(flare, uv).rgb
             : params.show == SHOW_THRESHOLD ? texture(bright, uv).rgb * 0.1
             : params.show == SHOW_LENS      ? (uv.y < 0.1 ? texture(lens_ramp, vec2(uv.x, 0.5)).rgb
                                                             : texture(dirt, uv).rgb + texture(starburst, uv).rgb)
                                             : texture(final, uv).rgb;
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
