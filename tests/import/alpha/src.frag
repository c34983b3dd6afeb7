// Image alpha is not shown: Shadertoy composites it opaque. The colour is fragCoord / iResolution,
// so the corners also check the bottom-left origin and the +0.5 pixel centres.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(fragCoord / iResolution.xy, 0.5, 0.0);
}
