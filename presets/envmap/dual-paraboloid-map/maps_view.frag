#version 450
// The two maps side by side (+z left, -z right) for the inset; outside the discs dark grey.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 view;
uniform sampler2DArray maps;
const vec3 kOutside = vec3(0.1);  // behind the (premultiplied, transparent) texels outside a disc
void main() {
    float layer = uv.x < 0.5 ? 0.0 : 1.0;
    vec4 c = textureLod(maps, vec3(fract(uv.x * 2.0), uv.y, layer), 0.0);
    view = vec4(c.rgb + (1.0 - c.a) * kOutside, 1.0);
}
