#version 450
// Colored blended OIT, resolve: the weighted average reflected colour with its coverage 1 - r,
// plus the opaque colour filtered by the product of the transmissions, per channel:
//   c = accum.rgb / max(accum.a, 1e-5) * (1 - r) + opaque * transmit.rgb
// (weighted-blended's resolve has opaque * r: the same when the transmission is grey).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D accum;
uniform sampler2D reveal;
uniform sampler2D transmit;
uniform sampler2D opaque;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 a = texelFetch(accum, p, 0);
    float r = texelFetch(reveal, p, 0).r;
    vec3 avg = a.rgb / max(a.a, 1e-5);
    color = vec4(avg * (1.0 - r) + texelFetch(opaque, p, 0).rgb * texelFetch(transmit, p, 0).rgb, 1.0);
}
