// The GI family's shared scene: a Cornell box lit by one spot light on the ceiling.
//
// Every presets/gi/ method that is compared with the path-traced reference
// (presets/gi/README.md, tests/bench/gi_compare.sh) renders exactly this scene from the same
// camera, so that their error against gi/path-tracing-reference measures the method, not the
// scene. It is built from the host's generator meshes, placed by the transforms below, so the
// same placements feed a raster draw (instances of one mesh: `plane` for the walls, `cube` for
// the blocks) and a ray query (`pl_bvh_closest` per instance with the inverse placement):
//
//   [meshes]
//   wall  = { generator = "plane", size = 2.0, instances = 5 }   # CORNELL_WALLS
//   block = { generator = "cube",  size = 1.0, instances = 2 }   # CORNELL_BLOCKS
//   [buffers]
//   scene = { generator = "bvh", meshes = ["wall", "block"] }     # mesh 0 = wall, 1 = block
//   [view]
//   camera = { orbit = { target = [0, 0, 0], distance = 3.9, yaw = 0, pitch = 0 }, fov = 40, near = 0.05, far = 20 }
//   [cameras]
//   light = { eye = [0, 0.95, 0], target = [0, -1, 0], fov = 120, near = 0.02, far = 4 }
//
// The box is [-1, 1]^3, open at z = +1 towards the camera; walls face inwards. Albedos are the
// classic Cornell values (white 0.73, red and green walls). The light is a spot: radiant
// intensity I(theta) = CORNELL_LIGHT_I * cone(theta), theta from straight down, a smooth cone
// from 50 to 60 degrees so shadow-map methods need no hard edge; it hits the side walls below
// y ~ 0.4, which is what makes the colour bleeding. Everything is diffuse (Lambert, rho/pi).
#ifndef PASSLAB_GI_CORNELL_GLSL
#define PASSLAB_GI_CORNELL_GLSL

const int CORNELL_WALLS = 5;   // instances of the `plane` mesh (size 2: [-1,1]^2 in XZ, normal +Y)
const int CORNELL_BLOCKS = 2;  // instances of the `cube` mesh (size 1: [-0.5,0.5]^3)
const int CORNELL_WALL_FLOOR = 0, CORNELL_WALL_CEILING = 1, CORNELL_WALL_BACK = 2,
          CORNELL_WALL_LEFT = 3, CORNELL_WALL_RIGHT = 4;

const vec3 CORNELL_LIGHT_POS = vec3(0.0, 0.95, 0.0);
const vec3 CORNELL_LIGHT_DIR = vec3(0.0, -1.0, 0.0);
const vec3 CORNELL_LIGHT_I = vec3(4.0);  // radiant intensity on the axis, W/sr per channel
const float CORNELL_CONE_INNER = 0.6427876;  // cos 50 degrees
const float CORNELL_CONE_OUTER = 0.5;        // cos 60 degrees

mat4 cornell_translate(vec3 t) { return mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, t.x, t.y, t.z, 1); }

// Rotation by angle a (radians) about +X, +Y, +Z, right-handed (column-major as GLSL stores it).
mat4 cornell_rot_x(float a) { float c = cos(a), s = sin(a); return mat4(1, 0, 0, 0, 0, c, s, 0, 0, -s, c, 0, 0, 0, 0, 1); }
mat4 cornell_rot_y(float a) { float c = cos(a), s = sin(a); return mat4(c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1); }
mat4 cornell_rot_z(float a) { float c = cos(a), s = sin(a); return mat4(c, s, 0, 0, -s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1); }
mat4 cornell_scale(vec3 s) { return mat4(s.x, 0, 0, 0, 0, s.y, 0, 0, 0, 0, s.z, 0, 0, 0, 0, 1); }

// world_from_object of wall i: the plane's +Y normal turned to face into the box.
mat4 cornell_wall(int i) {
    const float q = 1.5707963;
    if (i == CORNELL_WALL_FLOOR) return cornell_translate(vec3(0, -1, 0));
    if (i == CORNELL_WALL_CEILING) return cornell_translate(vec3(0, 1, 0)) * cornell_rot_x(2.0 * q);
    if (i == CORNELL_WALL_BACK) return cornell_translate(vec3(0, 0, -1)) * cornell_rot_x(q);   // +Y -> +Z
    if (i == CORNELL_WALL_LEFT) return cornell_translate(vec3(-1, 0, 0)) * cornell_rot_z(-q);  // +Y -> +X
    return cornell_translate(vec3(1, 0, 0)) * cornell_rot_z(q);                                // +Y -> -X
}

// world_from_object of block i: 0 the short block (front right), 1 the tall one (back left).
mat4 cornell_block(int i) {
    if (i == 0) return cornell_translate(vec3(0.35, -0.7, 0.3)) * cornell_rot_y(-0.3142) * cornell_scale(vec3(0.6));
    return cornell_translate(vec3(-0.35, -0.4, -0.35)) * cornell_rot_y(0.2967) * cornell_scale(vec3(0.6, 1.2, 0.6));
}

// Diffuse albedo of a wall (mesh 0) or block (mesh 1) instance.
vec3 cornell_albedo(int mesh, int instance) {
    if (mesh == 0 && instance == CORNELL_WALL_LEFT) return vec3(0.63, 0.065, 0.05);
    if (mesh == 0 && instance == CORNELL_WALL_RIGHT) return vec3(0.14, 0.45, 0.091);
    return vec3(0.73);
}

// Radiant intensity of the spot towards unit direction w (from the light outwards).
vec3 cornell_light_intensity(vec3 w) {
    return CORNELL_LIGHT_I * smoothstep(CORNELL_CONE_OUTER, CORNELL_CONE_INNER, dot(w, CORNELL_LIGHT_DIR));
}

// Direct irradiance from the spot at point p with normal n, visibility excluded:
// E = I(w) max(0, n.l) / d^2; the caller multiplies by rho/pi and the visibility for L_direct.
vec3 cornell_light_irradiance(vec3 p, vec3 n) {
    vec3 d = CORNELL_LIGHT_POS - p;
    float d2 = dot(d, d);
    vec3 l = d * inversesqrt(d2);
    return cornell_light_intensity(-l) * max(dot(n, l), 0.0) / d2;
}

#endif
