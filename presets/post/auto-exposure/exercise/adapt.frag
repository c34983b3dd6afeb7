#version 450
// EXERCISE — automatic exposure adaptation (002_644d46bdce7e5305.txt L658-665). This pass draws
// one texel, `adapted` (x: the adapted mean luminance), every frame. `lum` is the frame's
// luminance at 256x256 with a full mip chain (the preset's `mean` pass builds it each frame);
// `adapted_prev` is last frame's `adapted` (a history image). tonemap.frag then exposes the frame
// by params.key / adapted (002 L650). Fill in the two TODO blocks, then check your work:
//     passlab run   post/auto-exposure --exercise presets/post/auto-exposure/exercise   (live)
//     passlab grade post/auto-exposure --exercise presets/post/auto-exposure/exercise   (the cases)
// You have: frame.delta (this frame's dt, seconds), frame.index (0 on the first frame),
// params.rate (k, 2.5 per second in 002).
layout(location = 0) in vec2 uv;
layout(location = 0) out float adapted;
uniform sampler2D lum;
uniform sampler2D adapted_prev;
void main() {
    // TODO 1: this frame's mean luminance (L660: "mipmap the frame buffer object texture up to
    // 1x1"). Each level of lum's chain holds the means of 2x2 texels of the one before: which
    // level holds the mean of the whole image, and how do you make sure you read that level?
    float mean = 0.0;

    float prev = texelFetch(adapted_prev, ivec2(0), 0).r;

    // TODO 2: move the adapted value towards the mean like an eye (L662-664):
    //     previousLuminance = mix(previousLuminance, newLuminance, uAdaptionRate)
    //     uAdaptionRate     = 1 - exp(-dt * k)
    // The rate must depend on the frame time so that the eye adapts at the same speed at 30 and
    // at 120 frames per second (n frames of dt must compose to 1 - exp(-k n dt)). The first
    // frame has no past (its history holds nothing): start at the mean.
    adapted = prev;
}
