// The deferred presets' objects: the floor, and 64 instances of a radius-0.5 ball on a
// jittered 8 x 8 grid with hash-placed sizes and materials (used by scene.vert for drawing and
// by culling passes that need each object's bounding sphere).
#ifndef PASSLAB_DEFERRED_OBJECTS_GLSL
#define PASSLAB_DEFERRED_OBJECTS_GLSL
#include "common/hash.glsl"

const vec4 kFloorMaterial = vec4(0.55, 0.55, 0.5, 0.1);  // rgb albedo, a specular intensity
const float kFloorHalf = 8.0;                            // the 16 x 16 floor plane at y = 0
const float kBallMeshRadius = 0.5;                       // the sphere generator's radius

struct SceneBall {
    vec3 centre;    // world position of the mesh origin
    float scale;    // uniform scale of the mesh (bounding radius = kBallMeshRadius * scale)
    vec4 material;  // rgb albedo, a specular intensity
};

SceneBall scene_ball(int i) {
    vec3 h = hash_pcg3(vec3(float(i), 2.0, 11.0));
    vec2 cell = vec2(float(i % 8), float(i / 8)) - 3.5;
    float s = 0.5 + 0.5 * h.z;
    vec3 offset = vec3((cell + (h.xy - 0.5) * 0.6) * 1.6, 0.0);
    SceneBall b;
    b.centre = vec3(offset.x, 0.5 * s, offset.y);
    b.scale = s;
    b.material = vec4(0.25 + 0.7 * hash_pcg3(vec3(float(i), 7.0, 1.0)), 0.6 * h.y);
    return b;
}

// The crowd (deferred/clustered-forward, scene = crowd): kCrowdSide x kCrowdSide smaller balls,
// kCrowdBalls in all, on a jittered grid over the floor, each bobbing up and down with the
// frame clock (time in seconds) at its own hashed rate and phase — a few hundred moving
// objects under the same lights. Bounding radius kBallMeshRadius * scale, as for scene_ball.
const int kCrowdSide = 20, kCrowdBalls = kCrowdSide * kCrowdSide;
const float kCrowdSpacing = 0.7;  // grid step (world units): 20 x 0.7 = 14 of the 16-unit floor
const float kCrowdBob = 0.35;     // the largest lift above the floor (world units)

SceneBall scene_ball_crowd(int i, float time) {
    vec3 h = hash_pcg3(vec3(float(i), 23.0, 5.0));
    vec2 cell = vec2(float(i % kCrowdSide), float(i / kCrowdSide)) - 0.5 * float(kCrowdSide - 1);
    vec2 xz = (cell + (h.xy - 0.5) * 0.4) * kCrowdSpacing;
    float s = 0.4 + 0.35 * h.z;  // bounding radius 0.2 .. 0.375
    float bob = kCrowdBob * (0.5 - 0.5 * cos(time * (1.0 + 1.5 * h.x) + 6.2831853 * h.y));
    SceneBall b;
    b.centre = vec3(xz.x, kBallMeshRadius * s + bob, xz.y);
    b.scale = s;
    b.material = vec4(0.25 + 0.7 * hash_pcg3(vec3(float(i), 13.0, 3.0)), 0.6 * h.y);
    return b;
}
#endif
