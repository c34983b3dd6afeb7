#version 450
// Snell's law check: a random incidence angle and index pair per texel, refract(), and the
// residual |eta1 sin(theta1) - eta2 sin(theta2)| (0 where refract reports total reflection).
#include "common/hash.glsl"
layout(location = 0) out float snell;
void main() {
    vec3 h = hash_pcg3(vec3(gl_FragCoord.xy, 8.0));
    float n1 = 1.0 + 1.5 * h.x, n2 = 1.0 + 1.5 * h.y, theta1 = 1.55 * h.z;
    vec3 N = vec3(0.0, 0.0, 1.0), I = vec3(sin(theta1), 0.0, -cos(theta1));
    vec3 T = refract(I, N, n1 / n2);
    float sin2 = length(cross(T, -N)) / max(length(T), 1e-20);
    snell = dot(T, T) == 0.0 ? 0.0 : abs(n1 * sin(theta1) - n2 * sin2);
}
