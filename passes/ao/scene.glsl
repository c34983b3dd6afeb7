// presets/ao/precomputed-ao's scene, shared with raytrace/rt-ambient-occlusion's reference
// (which has no `scene` param: it stands in a constant params.scene and the SCENE_* defines).
// The baked scene: every surface is a parametric patch (u, v) in [0, 1]^2 -> point and normal,
// and the same function serves the bake (one AO texel per (u, v), like a light map, 004 L697)
// and the draw (a plane mesh whose vertices are moved onto the patch), so texel and surface
// cannot disagree. The occluders are the same shapes as analytic primitives (no BVH needed:
// eleven patches, five solids, passes/ao/raycast.glsl).
//
// Surfaces (patch id -> tile of the AO atlas, row-major in 4 x 4 tiles):
//   0 floor, 1 big ball, 2 small ball, 3..8 the box's faces (+x -x +y -y +z -z),
//   9 the bowl's inside, 10 the bowl's outside.
#ifndef AO_SCENE_GLSL
#define AO_SCENE_GLSL
#include "ao/raycast.glsl"

const int kSurfaces = 11, kAtlasCols = 4;  // a square atlas of 4 x 4 tiles, 11 used
const float kPi = 3.14159265358979;

const float kFloorHalf = 3.0;                       // floor: the square |x|, |z| <= 3 at y = 0
const vec3  kBallA = vec3(-1.2, 0.5, 0.3);          // resting on the floor (radius = height)
const float kBallARadius = 0.5;
const vec3  kBallB = vec3(-0.35, 0.3, 1.1);
const float kBallBRadius = 0.3;
const vec3  kBoxCentre = vec3(0.9, 0.45, -0.7);     // a 0.9 cube standing on the floor
const vec3  kBoxHalf = vec3(0.45);
const float kBowlRadius = 0.6;                      // hemisphere, rim at y = R, bottom on the floor
const vec3  kBowlCentre = vec3(0.85, 0.6, 1.0);

// Which solids exist in each scene (SCENE_* from the `scene` enum).
bool has_floor() { return params.scene == SCENE_OBJECTS || params.scene == SCENE_CREASE; }
bool has_balls() { return params.scene == SCENE_OBJECTS; }
bool has_ball_a() { return has_balls() || params.scene == SCENE_SPHERE; }
bool has_box() { return params.scene == SCENE_OBJECTS || params.scene == SCENE_BOX || params.scene == SCENE_CREASE; }
bool has_bowl() { return params.scene == SCENE_OBJECTS || params.scene == SCENE_BOWL; }

bool surface_present(int id) {
    if (id == 0) return has_floor();
    if (id == 1) return has_ball_a();
    if (id == 2) return has_balls();
    if (id <= 8) return has_box();
    return has_bowl();
}

// Patch id at (u, v) -> world point p and unit normal n.
void surface_point(int id, vec2 uv, out vec3 p, out vec3 n) {
    if (id == 0) {
        p = vec3(mix(-kFloorHalf, kFloorHalf, uv.x), 0.0, mix(-kFloorHalf, kFloorHalf, uv.y));
        n = vec3(0.0, 1.0, 0.0);
    } else if (id <= 2) {  // sphere: theta = pi v from the top, phi = 2 pi u
        float theta = kPi * uv.y, phi = 2.0 * kPi * uv.x;
        n = vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
        p = (id == 1 ? kBallA : kBallB) + (id == 1 ? kBallARadius : kBallBRadius) * n;
    } else if (id <= 8) {  // box face: axis k, sign s; (u, v) spans the two other axes
        int f = id - 3, k = f / 2;
        float s = (f % 2 == 0) ? 1.0 : -1.0;
        n = vec3(0.0);
        n[k] = s;
        vec3 a = vec3(0.0), b = vec3(0.0);
        a[(k + 1) % 3] = 1.0;
        b[(k + 2) % 3] = 1.0;
        p = kBoxCentre + kBoxHalf * (n + (2.0 * uv.x - 1.0) * a + (2.0 * uv.y - 1.0) * b);
    } else {  // bowl: psi = (pi / 2) v up from the bottom, phi = 2 pi u
        float psi = 0.5 * kPi * uv.y, phi = 2.0 * kPi * uv.x;
        vec3 d = vec3(sin(psi) * cos(phi), -cos(psi), sin(psi) * sin(phi));
        p = kBowlCentre + kBowlRadius * d;
        n = id == 9 ? -d : d;  // inside faces the centre
    }
}

// Any occluder on the ray o + t w, 0 < t <= t_max (the feeler's length).
bool scene_occluded(vec3 o, vec3 w, float t_max) {
    if (has_floor() && ray_hits_square_y(o, w, vec3(0.0), kFloorHalf, t_max)) return true;
    if (has_ball_a() && ray_hits_sphere(o, w, kBallA, kBallARadius, t_max)) return true;
    if (has_balls() && ray_hits_sphere(o, w, kBallB, kBallBRadius, t_max)) return true;
    if (has_box() && ray_hits_box(o, w, kBoxCentre, kBoxHalf, t_max)) return true;
    if (has_bowl() && ray_hits_bowl(o, w, kBowlCentre, kBowlRadius, t_max)) return true;
    return false;
}

// Tile of patch id in the atlas, in tiles.
vec2 atlas_tile(int id) { return vec2(float(id % kAtlasCols), float(id / kAtlasCols)); }
#endif
