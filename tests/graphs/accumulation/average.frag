#version 450
// Progressive average: accum = mix(accum_prev, sample, 1 / (n + 1)) with n = frame.accum_frame,
// so frame n weighs like the others and a change (n = 0) replaces the history by one sample.
// The sample is the frame index plus a param, so the mean is a closed form: (N - 1) / 2 + offset.
layout(location = 0) out vec4 color;
uniform sampler2D accum_prev;
void main() {
    float n = float(frame.accum_frame);
    float s = float(frame.index) + params.offset;
    float mean = mix(texelFetch(accum_prev, ivec2(gl_FragCoord.xy), 0).r, s, 1.0 / (n + 1.0));
    color = vec4(mean, n, float(frame.index), 1.0);
}
