// EXERCISE — the planar mirror's geometry (000_c9f7e5de708ecbb3.txt L3859-3944), shadowing
// passes/mirror/mirror.glsl for envmap/planar-reflection-stencil. The preset reflects the scene
// about the floor plane n.x = d (n = kMirrorNormal, d = kMirrorOffset) and draws it where the
// stencil marks the mirror; these functions are what it reflects with. Fill in the three TODO
// blocks, then check your work against the reference:
//     passlab run   envmap/planar-reflection-stencil --exercise presets/envmap/planar-reflection-stencil/exercise
//     passlab grade envmap/planar-reflection-stencil --exercise presets/envmap/planar-reflection-stencil/exercise
// The lecture reflects about the plane z = 0 with Scale(1, 1, -1) (L3868-3869); here the plane is
// the floor, and the matrix should work for any unit n and offset d.
#ifndef PASSLAB_MIRROR_GLSL
#define PASSLAB_MIRROR_GLSL
#include "common/camera.glsl"

const vec3 kMirrorNormal = vec3(0.0, 1.0, 0.0);  // the mirror faces +y
const float kMirrorOffset = 0.0;                  // n.x = d: the floor y = 0
const float kMirrorHalf = 1.5;                    // the mirror is the square |x|, |z| <= 1.5

// TODO 1: the reflection about the plane n.x = d as a 4x4 matrix M (column-major: mat4(c0, c1,
// c2, c3)). A point p has signed distance s = n.p - d from the plane; its mirror image lies the
// same distance on the other side, along n. Write that as a linear part (a 3x3 matrix built from
// n n^T) and a translation (built from d and n). Check: for n = (0, 0, 1), d = 0 you must get
// the lecture's Scale(1, 1, -1); M M = I and det M = -1 (which is why the reflected passes
// set front_face = "cw", L3870-3872 and L3936-3937).
mat4 mirror_matrix() {
    return mat4(1.0);
}
// TODO 2: the same reflection applied to a point (the eye: shading happens in the real world
// seen from the mirrored eye) and to a direction (no translation).
vec3 mirror_point(vec3 p) { return p; }
vec3 mirror_direction(vec3 v) { return v; }
// TODO 3: written to gl_ClipDistance[0] for reflected geometry (mirror/scene.vert, at the
// unreflected point p), this must cut away whatever lies behind the mirror (L3938-3939: "if
// scene intersects mirror plane, need to clip against plane"): the hardware keeps a vertex
// where the value is >= 0 and clips where it is < 0. Return the signed distance of p to the
// plane, positive on the side the mirror faces.
float mirror_side(vec3 p) { return 1.0; }

// The mirrored camera for render-to-texture (000 L3946-3964): eye, forward and up reflected,
// then built as an ordinary (right-handed, proper) camera with look_at. Its right vector is
// cross(M f, M u) = -M (f x u): the image is the x-flipped view of the mirrored world, so no
// winding flip is needed when drawing from it, and the projective lookup flips it back.
mat4 mirror_camera_view() {
    vec3 eye = frame.camera_pos.xyz;
    vec3 f = -vec3(frame.view[0][2], frame.view[1][2], frame.view[2][2]);  // third row of view = -f
    vec3 u = vec3(frame.view[0][1], frame.view[1][1], frame.view[2][1]);
    vec3 e = mirror_point(eye);
    return look_at(e, e + mirror_direction(f), mirror_direction(u));
}
mat4 mirror_camera_view_proj() { return frame.proj * mirror_camera_view(); }
#endif
