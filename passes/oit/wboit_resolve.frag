#version 450
// Weighted blended OIT, resolve (002_644d46bdce7e5305.txt L1826-1828: "rgb / max(a, 1e-5)"):
// the weighted average colour, shown with coverage 1 - revealage over the opaque colour:
//   c = accum.rgb / max(accum.a, 1e-5) * (1 - reveal) + opaque * reveal
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D accum;
uniform sampler2D reveal;
uniform sampler2D opaque;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 a = texelFetch(accum, p, 0);
    float r = texelFetch(reveal, p, 0).r;
    vec3 behind = texelFetch(opaque, p, 0).rgb;
    // normalise the weighted sum (L1826-1828) and composite with coverage 1 - r
    vec3 avg = a.rgb / max(a.a, 1e-5);
    color = vec4(mix(behind, avg, 1.0 - r), 1.0);
}
