#version 450
// EXERCISE — the MSAA resolve (000_c9f7e5de708ecbb3.txt L3321-3353). The draw has already run the
// fragment shader once per pixel (L3326) and stored that colour in every one of the pixel's 4
// samples that the triangle covers (the others keep the background). Your shader turns the 4
// samples of each pixel of `ms` into one colour; the display shows your result on the right,
// and the cases compare it with the hardware's resolve.
//     passlab run   aa/msaa --exercise presets/aa/msaa/exercise   (live, hot reload)
//     passlab grade aa/msaa --exercise presets/aa/msaa/exercise   (the test cases)
// A multisampled image is read one sample at a time: texelFetch(ms, ivec2 pixel, int sample);
// textureSamples(ms) is the number of samples per pixel.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 resolved;
uniform sampler2DMS ms;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 sum = vec4(0.0);
    // TODO 1: visit every sample of pixel p and accumulate it in sum. (The shader ran once per
    // pixel, but the samples do not all hold its colour: coverage was decided per sample.)

    // TODO 2: the output colour is "blended based on number of covered samples" (L3327):
    //     resolved = (1 / S) * sum over s in [0, S) of ms(p, s)
    // every sample weighs the same and the weights sum to 1.
    resolved = vec4(0.0, 0.0, 0.0, 1.0);
}
