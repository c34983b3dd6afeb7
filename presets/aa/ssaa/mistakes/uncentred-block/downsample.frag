#version 450
// Box filter (000_c9f7e5de708ecbb3.txt L3308-3309: "downsample final colour texture to target
// resolution using fullscreen shader; box filter, Lanczos filter, Gaussian"): each pixel is the
// mean of the N x N samples it covers in the N x image.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 result;
uniform sampler2D hi;
void main() {
    int n = params.n;
    ivec2 base = ivec2(gl_FragCoord.xy * float(n));   // the pixel's centre, not its corner
    vec4 sum = vec4(0.0);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) sum += texelFetch(hi, base + ivec2(x, y), 0);
    result = sum / float(n * n);
}
