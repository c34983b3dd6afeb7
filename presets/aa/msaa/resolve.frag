#version 450
// The resolve, written out (000_c9f7e5de708ecbb3.txt L3349-3352 does it with glBlitFramebuffer;
// Vulkan's resolve attachment, the `res` image here, does the same): a pixel's colour is the
// mean of its samples, so an edge pixel is "blended based on number of covered samples"
// (L3327): with k of the 4 samples covered, k/4 x colour + (4 - k)/4 x background.
//     res_shader(p) = (1 / S) * sum over s in [0, S) of ms(p, s),   S = textureSamples(ms) = 4
// The draw ran the fragment shader once per pixel (L3326) and wrote that one colour to every
// covered sample; the samples of a pixel differ only in what covered them.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 resolved;
uniform sampler2DMS ms;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int count = textureSamples(ms);
    vec4 sum = vec4(0.0);
    for (int s = 0; s < count; ++s) sum += texelFetch(ms, p, s);
    resolved = sum / float(count);
}
