#version 450
// Display: exposure tone map 1 - exp(-exposure L) of the radiance in `src` (the seed leaves the
// tone mapping to the engine; this one is monotone and never clips), into an sRGB target.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D src;
void main() {
    vec3 c = texture(src, uv).rgb;
    color = vec4(1.0 - exp(-params.exposure * c), 1.0);
}
