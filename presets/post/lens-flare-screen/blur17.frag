#version 450
// 002 L824-846: "separate linear interpolator optimized 17x17 gaussian blur": 4 symmetric pairs
// of bilinear lookups at 0.649, 2.406, 4.335 and 6.271 texels, each lookup placed between two
// discrete taps so it fetches both with their weights. As printed the 8 weights sum to 0.99764,
// not 1 (the kernel is truncated, 0.24% of the energy is lost per pass); we keep the printed
// constants. x with BLUR_X, else y. With params.blur off the image passes through.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 blur_out;
uniform sampler2D blur_in;

const float kOffset[4] = float[](0.6494988171273325, 2.405752812667325, 4.334747038826614, 6.27051066767145);
const float kWeight[4] = float[](0.22251469736395335, 0.1934401294345523, 0.06915657278613227, 0.013708153234290525);
#ifdef BLUR_X
const vec2 kDir = vec2(1.0, 0.0);
#else
const vec2 kDir = vec2(0.0, 1.0);
#endif

void main() {
    if (!params.blur) {
        blur_out = texelFetch(blur_in, ivec2(gl_FragCoord.xy), 0);
        return;
    }
    vec2 step = kDir / vec2(textureSize(blur_in, 0));
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 4; ++i)
        sum += (textureLod(blur_in, uv + step * kOffset[i], 0.0) + textureLod(blur_in, uv - step * kOffset[i], 0.0)) * kWeight[i];
    blur_out = sum;
}
