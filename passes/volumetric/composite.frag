#version 450
// L = L_surface T_view + L_in: the surface radiance (0 where no surface: the sky) attenuated by
// the view ray's transmittance, plus the in-scatter of the march. `inscatter` and `transmit` may be
// smaller than the view (the live view marches at 1/scale resolution): sampled bilinearly.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 display;   // tonemap.frag's 1 - exp(-exposure L), in the same pass
uniform sampler2D surface;
uniform sampler2D inscatter;
uniform sampler2D transmit;
void main() {
    vec3 s = texelFetch(surface, ivec2(gl_FragCoord.xy), 0).rgb;
    vec3 l_in, t;
    if (textureSize(inscatter, 0) == ivec2(frame.target.xy)) {
        l_in = texelFetch(inscatter, ivec2(gl_FragCoord.xy), 0).rgb;
        t = texelFetch(transmit, ivec2(gl_FragCoord.xy), 0).rgb;
    } else {
        l_in = texture(inscatter, uv).rgb;
        t = texture(transmit, uv).rgb;
    }
    color = vec4(s * t + l_in, 1.0);
    display = vec4(1.0 - exp(-params.exposure * color.rgb), 1.0);
}
