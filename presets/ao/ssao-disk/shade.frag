#version 450
// The ambient term darkened by the visibility (004 L719: "use in the lighting model as a
// factor"), plus a weak key light so shapes stay readable.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 lit;
uniform sampler2D normal;
uniform sampler2D ao;
void main() {
    vec4 nw = texture(normal, uv);
    float v = texture(ao, uv).r;
    if (params.show == SHOW_AO) {
        lit = vec4(vec3(v), 1.0);
        return;
    }
    if (nw.w == 0.0) {
        lit = vec4(0.6, 0.7, 0.85, 1.0);
        return;
    }
    vec3 n_world = normalize(transpose(mat3(frame.view)) * nw.xyz);
    vec3 ambient = mix(vec3(0.3, 0.28, 0.27), vec3(0.55, 0.6, 0.7), 0.5 + 0.5 * n_world.y);
    float key = max(dot(n_world, normalize(vec3(0.4, 0.8, 0.3))), 0.0);
    lit = vec4(ambient * v + 0.25 * key * vec3(1.0, 0.95, 0.85), 1.0);
}
