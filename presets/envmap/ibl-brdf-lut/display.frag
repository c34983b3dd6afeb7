#version 450
// The table with n.v = 1 at the top (as usually drawn: roughness right, n.v up).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D lut;
void main() {
    vec4 t = texture(lut, vec2(uv.x, 1.0 - uv.y));
    vec3 c = params.show == SHOW_SCALE ? vec3(t.r) : params.show == SHOW_BIAS ? vec3(t.g) * 4.0 : params.show == SHOW_SUM ? vec3(t.b) : vec3(t.rg, 0.0);
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
