// EXERCISE — the six cameras of a dynamic cube map (001_fe43b953f362fae7.txt L106-127,
// 000_c9f7e5de708ecbb3.txt L2335-2340: "generate views of the environment, one for each cube
// face, 90 degree view frustum, render directly to a texture"). Shadows
// passes/envmap/cube_face_camera.glsl for envmap/cube-map-dynamic: every version of the cube-map
// pass (six passes, geometry shader, vertex layer) projects the scene with these two functions.
// Fill in the two TODO blocks, then check your work against the reference:
//     passlab run   envmap/cube-map-dynamic --exercise presets/envmap/cube-map-dynamic/exercise
//     passlab grade envmap/cube-map-dynamic --exercise presets/envmap/cube-map-dynamic/exercise
// Live, `--set sky=smooth --set objects=false` makes any seam between faces visible in the
// inset (the unfolded cube map) and on the mirror ball.
//
// Face f has three axes: c (the face's outward axis, the camera's forward), a (the direction of
// growing s, to the right of the face image) and b (growing t, downwards in the image):
//     unnormalised direction d = s a + t b + c,   s, t in [-1, 1]
// The sampler decides which texel a direction reads; the camera must put the scene there.
// Pitfall (001 L123-127, "addressing not intuitive (needs flip)"): the faces are mirror images
// of what a right-handed camera would see, so every triangle's winding flips: the passes render
// with front_face = "cw".
#ifndef PASSLAB_CUBE_FACE_CAMERA_GLSL
#define PASSLAB_CUBE_FACE_CAMERA_GLSL
// TODO 1: the columns a, b, c of face `face`, in Vulkan order +X, -X, +Y, -Y, +Z, -Z. They must
// agree with the sampler's addressing (000 L2317-2333; Vulkan spec "Cube Map Face Selection"),
// which passes/envmap/cube.glsl writes out as cube_face_direction(face, uv): the direction a
// face texel stands for. Each face's (a, b) must be its own "right" and "down", not those of a
// neighbouring face or a flipped copy, or the images will not join at the edges.
mat3 cube_face_basis(int face) {
    return mat3(1.0);
}

// Clip-space position on face `face` of a point at offset v from the cube map's centre.
vec4 cube_face_clip(int face, vec3 v, float near, float far) {
    // TODO 2: a perspective camera at the centre looking along c that sees exactly the face:
    // a point at v (from the centre) lands at s = (v.a)/(v.c), t = (v.b)/(v.c), so the frustum
    // is 90 degrees wide in both directions (000 L2339) and square whatever the window's shape.
    // In Vulkan clip space (x right, y down, z/w in [0, 1], w the distance along c):
    //     clip = (x, y, z, w) with x/w = s, y/w = t, and z/w running from 0 at v.c = near to 1
    //     at v.c = far.
    return vec4(0.0, 0.0, 0.0, 1.0);
}
#endif
