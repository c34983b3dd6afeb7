// The dynamic scene around the mirror ball, shared by the main view and the cube-map passes: a
// ring of N_CUBES spinning, orbiting boxes (instances 0 .. N_CUBES-1 of the cube mesh) and a sky
// box (instance N_CUBES) whose colour is the environment in the direction from the centre.
// Everything moves with frame.time, which is why the cube map is re-rendered every frame.
#include "envmap/sky.glsl"
#include "envmap/smooth_env.glsl"
const int kCubes = 6;              // orbiting boxes
const float kOrbit = 1.35;         // their distance from the mirror ball's centre (the cube map's centre)
const vec3 kCubeCentre = vec3(0.0);  // the cube map's camera sits at the mirror ball's centre
const float kCubeNear = 0.05, kCubeFar = 100.0;  // its depth range (the boxes come no closer than 1)
const float kBoxSize = 0.34;       // edge of an orbiting box (the mesh is a unit cube)
const float kSkyBox = -40.0;       // sky box scale: half-size 20, corners at 35 (inside far = 100). Negative: p -> -p is a
                                   // point reflection (determinant -1), which turns the box's outward-facing
                                   // triangles into inward-facing ones, seen from inside with back-face culling.

// World position of mesh vertex p of instance i at time t (rotation about y, then the orbit).
vec3 scene_world(vec3 p, int i, float t) {
    if (i == kCubes) return kSkyBox * p;
    float a = t * params.speed + 6.2831853 * float(i) / float(kCubes), spin = 2.0 * a + float(i);
    mat3 r = mat3(cos(spin), 0.0, -sin(spin), 0.0, 1.0, 0.0, sin(spin), 0.0, cos(spin));
    vec3 centre = vec3(kOrbit * cos(a), 0.35 * sin(3.0 * a + float(i)), kOrbit * sin(a));
    return centre + r * (kBoxSize * p);
}

vec3 scene_normal(vec3 n, int i, float t) {
    if (i == kCubes) return n;
    return (scene_world(n, i, t) - scene_world(vec3(0.0), i, t)) / kBoxSize;  // the rotation only
}

// The environment in world direction d: the procedural sky, or (SKY_SMOOTH) the smooth field
// 0.5 + 0.35 d of smooth_env.glsl, whose colour names the direction, for the seam test.
vec3 scene_environment(vec3 d) {
    return params.sky == SKY_SMOOTH ? smooth_environment(d) : sky_radiance(d, params.sun_dir, 1.0);
}

vec3 scene_albedo(int i) {
    const vec3 k[kCubes] = vec3[](vec3(0.9, 0.15, 0.1), vec3(0.95, 0.7, 0.1), vec3(0.2, 0.8, 0.25),
                                  vec3(0.1, 0.6, 0.9), vec3(0.45, 0.2, 0.9), vec3(0.95, 0.95, 0.95));
    return k[i];
}

// Hidden instances (the boxes when params.objects is off) are moved out of every clip volume.
bool scene_visible(int i) { return i == kCubes || params.objects; }
