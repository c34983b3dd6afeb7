#version 450
// The stencil invariant, per pixel: reflected fragments written where the mirror does not cover
// the pixel:  leak * (1 - mask). Must be 0 everywhere (docs/catalogue.md); `reflected` is the
// mask target the reflected passes wrote, `mask` the mirror's coverage (what the stencil holds).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 outside;
uniform sampler2D reflected;
uniform sampler2D mask;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    outside = vec4(texelFetch(reflected, p, 0).r * (1.0 - texelFetch(mask, p, 0).r), 0.0, 0.0, 1.0);
}
