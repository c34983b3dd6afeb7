#version 450
// The live lab's view: the geomorphing teapot (param `morph`), grey Lambert on a dark ground.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D src;
void main() {
    vec4 x = texelFetch(src, ivec2(gl_FragCoord.xy), 0);
    color = vec4(x.a > 0.0 ? vec3(0.1 + 0.85 * x.r) : vec3(0.04, 0.05, 0.07), 1.0);
}
