// The camera of a cube-map face, the inverse of cube_face_direction (cube.glsl). 001_fe43b953f362fae7.txt
// L106-120 / 000_c9f7e5de708ecbb3.txt L2335-2340: "generate views of the environment, one for
// each cube face, 90 degree view frustum, render directly to a texture".
//
// Face f has three axes: c (the face's outward axis, the camera's forward), a (the direction of
// growing s, to the right of the face image) and b (growing t, downwards):
//     unnormalised direction d = s a + t b + c,   s, t in [-1, 1]
// so a point at v = p - centre projects to s = (v.a)/(v.c), t = (v.b)/(v.c): a 90 degree
// perspective with w = v.c. In Vulkan clip space (x right, y down, z/w in [0, 1]):
//     clip = (v.a, v.b, far/(far - near) (v.c - near), v.c)
// which puts face texel (x, y) exactly on the direction cube_face_direction(f, (x, y) + 0.5)/n.
// Pitfall (001 L123-127, "addressing not intuitive (needs flip)"): the cube-map faces are mirror
// images of what a right-handed camera would see (face +X: a = -z, b = -y, and -z x -y = -x is
// not the forward axis +x), so every triangle's winding flips: render faces with
// front_face = "cw" (or cull none).
#ifndef PASSLAB_CUBE_FACE_CAMERA_GLSL
#define PASSLAB_CUBE_FACE_CAMERA_GLSL
// Columns a, b, c of face `face` in Vulkan order +X, -X, +Y, -Y, +Z, -Z (as cube.glsl).
mat3 cube_face_basis(int face) {
    return face == 0 ? mat3(vec3(0, 0, -1), vec3(0, -1, 0), vec3(1, 0, 0))
         : face == 1 ? mat3(vec3(0, 0, 1), vec3(0, -1, 0), vec3(-1, 0, 0))
         : face == 2 ? mat3(vec3(1, 0, 0), vec3(0, 0, 1), vec3(0, 1, 0))
         : face == 3 ? mat3(vec3(1, 0, 0), vec3(0, 0, -1), vec3(0, -1, 0))
         : face == 4 ? mat3(vec3(1, 0, 0), vec3(0, -1, 0), vec3(0, 0, 1))
                     : mat3(vec3(-1, 0, 0), vec3(0, -1, 0), vec3(0, 0, -1));
}

// Clip-space position on face `face` of a point at offset v from the cube map's centre.
vec4 cube_face_clip(int face, vec3 v, float near, float far) {
    vec3 f = v * cube_face_basis(face);  // (v.a, v.b, v.c): the transpose = inverse of an orthonormal basis
    return vec4(f.x / frame.aspect, f.y, far / (far - near) * (f.z - near), f.z);   // 90 degrees vertically, the view's aspect
}
#endif
