// Cube map face geometry (000_c9f7e5de708ecbb3.txt L2317-2333: addressing by (s, t, r), the
// highest-magnitude component picks the face, the others are divided by it; 001_fe43b953f362fae7.txt
// L88-101 the same with the remap to [0, 1], L123-127 "addressing not intuitive (needs flip)"):
// a direction selects the face of its largest component; the other two, divided by
// it, give (s, t) in [-1, 1]. Vulkan (and GL) face order +X, -X, +Y, -Y, +Z, -Z, with
// t growing downwards on every face. Inverted here: the direction a face texel stands for, so a
// pass can render each face (repeat = 6, layer = "iteration").
#ifndef PASSLAB_CUBE_GLSL
#define PASSLAB_CUBE_GLSL
vec3 cube_face_direction(int face, vec2 uv) {
    float s = uv.x * 2.0 - 1.0, t = uv.y * 2.0 - 1.0;
    vec3 d = face == 0 ? vec3(1.0, -t, -s)
           : face == 1 ? vec3(-1.0, -t, s)
           : face == 2 ? vec3(s, 1.0, t)
           : face == 3 ? vec3(s, -1.0, -t)
           : face == 4 ? vec3(s, -t, 1.0)
                       : vec3(-s, -t, -1.0);
    return normalize(d);
}
#endif
