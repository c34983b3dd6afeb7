// Buffer A reads itself: Shadertoy shows it the previous frame, zero before the first.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 last = texelFetch(iChannel0, ivec2(fragCoord), 0);
    fragColor = vec4(last.r + 1.0, float(iFrame), last.b + iTimeDelta, 1.0);
}
