#version 450
// Lambert with a little ambient and, with WIRE, the sub-triangle edges; with DEPTH the window
// depth itself (the planar test compares positions, not shading).
layout(location = 0) in vec3 g_normal;
layout(location = 1) in vec2 g_bary2;
layout(location = 0) out vec4 color;
void main() {
#ifdef DEPTH
    color = vec4(gl_FragCoord.z, 0.0, 0.0, 1.0);
#else
    vec3 n = normalize(g_normal) * (gl_FrontFacing ? 1.0 : -1.0);
    float l = 0.15 + 0.85 * max(dot(n, normalize(vec3(0.4, 0.8, 0.5))), 0.0);
    vec3 c = BASE * l;
    if (params.wire) {
        vec3 g_bary = vec3(g_bary2, 1.0 - g_bary2.x - g_bary2.y);
        vec3 d = fwidth(g_bary);
        vec3 a = smoothstep(vec3(0.0), 1.5 * d, g_bary);
        c = mix(vec3(0.05), c, min(a.x, min(a.y, a.z)));
    }
    color = vec4(c, 1.0);
#endif
}
