#version 450
// Seam check: texel (e, f) = the largest colour difference between the texels on both sides of
// edge e of face f, over every texel along the edge. From the edge point p (s or t = +-1 on face
// f), the texel inside f is p - (1/n) u (u: the in-face axis towards the edge), the texel across
// the edge p - (1/n) c (c: face f's axis): both are texel centres at the same position along
// the edge, one texel pitch apart. On a smooth environment they differ only by the field's
// change over that pitch; a face rendered flipped or rotated differs by the field's range.
#include "envmap/cube_face_camera.glsl"
layout(location = 0) out float seam;
uniform samplerCube env;  // lookups at texel centres: linear filtering returns the texel itself
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int edge = p.x, face = p.y;  // edges: s = +1, s = -1, t = +1, t = -1
    mat3 B = cube_face_basis(face);
    int n = textureSize(env, 0).x;
    float side = (edge & 1) == 0 ? 1.0 : -1.0, pitch = 1.0 / float(n);
    vec3 u = side * (edge < 2 ? B[0] : B[1]), w = edge < 2 ? B[1] : B[0];
    float worst = 0.0;
    for (int k = 0; k < n; ++k) {
        vec3 q = u + (-1.0 + (2.0 * float(k) + 1.0) * pitch) * w + B[2];  // on the edge, at texel k
        vec3 a = textureLod(env, q - pitch * u, 0.0).rgb, b = textureLod(env, q - pitch * B[2], 0.0).rgb;
        vec3 d = abs(a - b);
        worst = max(worst, max(d.r, max(d.g, d.b)));
    }
    seam = worst;
}
