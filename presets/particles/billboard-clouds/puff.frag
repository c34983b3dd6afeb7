#version 450
// Opaque puff: the disc |corner| <= 1 of the quad is kept, the rest discarded (alpha test, no
// blending, so the depth test sorts the puffs and the order does not matter). Shaded as the
// sphere it stands for, n = (x, y, sqrt(1 - x^2 - y^2)) in view space, lit from the upper left.
// Target 1 marks the covered pixels for the coverage test.
layout(location = 0) in vec2 corner;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 covered;
void main() {
    float r2 = dot(corner, corner);
    if (r2 > 1.0) discard;
    vec3 n = vec3(corner, sqrt(1.0 - r2));
    float l = 0.55 + 0.45 * max(dot(n, normalize(vec3(-0.4, 0.6, 0.7))), 0.0);
    color = vec4(vec3(0.93, 0.94, 0.97) * l, 1.0);
    covered = vec4(1.0);
}
