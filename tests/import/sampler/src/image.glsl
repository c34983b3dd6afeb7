// quad.png is 2x2: top row red | blue, bottom row green | white.
// Four vertical strips, each one channel's sample at a fixed uv (Shadertoy's v = 0 is the bottom):
//   0: vflip = true  at (0.25, 0.75): the picture's top-left, red
//   1: vflip = false at (0.25, 0.75): the picture upside down, its bottom-left, green
//   2: wrap repeat   at (1.25, 0.75): u wraps to 0.25, red
//   3: wrap clamp    at (1.25, 0.75): u clamps to the right column, blue
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int strip = int(fragCoord.x / iResolution.x * 4.0);
    vec2 at = strip < 2 ? vec2(0.25, 0.75) : vec2(1.25, 0.75);
    vec4 c = strip == 0 ? texture(iChannel0, at)
           : strip == 1 ? texture(iChannel1, at)
           : strip == 2 ? texture(iChannel2, at)
                        : texture(iChannel3, at);
    fragColor = vec4(c.rgb, 1.0);
}
