#version 450
// The ambient term once per pixel, before the lights add up on top of it.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 lit;
uniform sampler2D albedo;
uniform sampler2D normal;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    bool geometry = texelFetch(normal, px, 0).w != 0.0;
    lit = vec4(geometry ? params.ambient * texelFetch(albedo, px, 0).rgb : vec3(0.0), 1.0);
}
