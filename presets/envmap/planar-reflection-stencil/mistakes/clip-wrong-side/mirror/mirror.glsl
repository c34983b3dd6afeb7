// A planar mirror and what it does to points, directions and cameras (000_c9f7e5de708ecbb3.txt
// L3859-3944). The lecture reflects about the plane z = 0 with Scale(1, 1, -1); in general, for
// the plane n.x = d (|n| = 1) the reflection is the Householder matrix
//     M = | I - 2 n n^T   2 d n |        (M = M^-1, det M = -1: it turns the winding around)
//         | 0             1     |
// which for n = (0, 0, 1), d = 0 is exactly Scale(1, 1, -1). The presets use the floor y = 0
// (n = (0, 1, 0)), where M = Scale(1, -1, 1): the same matrix with the axes renamed.
#ifndef PASSLAB_MIRROR_GLSL
#define PASSLAB_MIRROR_GLSL
#include "common/camera.glsl"

const vec3 kMirrorNormal = vec3(0.0, 1.0, 0.0);  // the mirror faces +y
const float kMirrorOffset = 0.0;                  // n.x = d: the floor y = 0
const float kMirrorHalf = 1.5;                    // the mirror is the square |x|, |z| <= 1.5

mat4 mirror_matrix() {
    vec3 n = kMirrorNormal;
    mat3 r = mat3(1.0) - 2.0 * outerProduct(n, n);
    return mat4(vec4(r[0], 0.0), vec4(r[1], 0.0), vec4(r[2], 0.0), vec4(2.0 * kMirrorOffset * n, 1.0));
}
vec3 mirror_point(vec3 p) { return p - 2.0 * (dot(p, kMirrorNormal) - kMirrorOffset) * kMirrorNormal; }
vec3 mirror_direction(vec3 v) { return v - 2.0 * dot(v, kMirrorNormal) * kMirrorNormal; }
// Signed distance to the plane: > 0 on the side the mirror faces. Written to gl_ClipDistance[0]
// for reflected geometry, it cuts away what lies behind the mirror (000 L3938-3939: "if scene
// intersects mirror plane, need to clip against plane").
float mirror_side(vec3 p) { return kMirrorOffset - dot(p, kMirrorNormal); }   // distance below the mirror

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
