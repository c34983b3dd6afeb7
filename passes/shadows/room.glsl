// A closed room around the shared shadow scene, for point lights (omni-cube-shadows,
// dual-paraboloid-shadows): the shared 6 x 6 ground is its floor, and one instanced plane mesh,
// { generator = "plane", size = 6, instances = 5 }, gives the ceiling at y = ROOM_HEIGHT and the
// four walls at x = +-3, z = +-3, every one facing into the room. Closed, so every direction from
// a light inside hits a receiver: the whole cube (or both paraboloids) holds depths, and every
// face seam crosses a surface.
#ifndef PASSLAB_SHADOWS_ROOM_GLSL
#define PASSLAB_SHADOWS_ROOM_GLSL
#define ROOM_SURFACES 5
const float ROOM_HEIGHT = 4.0;

// World from the plane's object space (x, z in [-3, 3], normal +y) for surface i: a rotation
// taking +y to the inward normal (columns: where object x, y, z go; determinant +1, so the
// winding and the normal stay consistent), the walls' object z scaled by 4/6 to the room's height.
mat4 room_model(int i) {
    const float s = ROOM_HEIGHT / 6.0, h = 0.5 * ROOM_HEIGHT;
    if (i == 0) return mat4(vec4(1, 0, 0, 0), vec4(0, -1, 0, 0), vec4(0, 0, -1, 0), vec4(0, ROOM_HEIGHT, 0, 1));  // ceiling
    if (i == 1) return mat4(vec4(0, 0, 1, 0), vec4(1, 0, 0, 0), vec4(0, s, 0, 0), vec4(-3, h, 0, 1));            // x = -3
    if (i == 2) return mat4(vec4(0, 0, -1, 0), vec4(-1, 0, 0, 0), vec4(0, s, 0, 0), vec4(3, h, 0, 1));           // x = +3
    if (i == 3) return mat4(vec4(-1, 0, 0, 0), vec4(0, 0, 1, 0), vec4(0, s, 0, 0), vec4(0, h, -3, 1));           // z = -3
    return mat4(vec4(1, 0, 0, 0), vec4(0, 0, -1, 0), vec4(0, s, 0, 0), vec4(0, h, 3, 1));                        // z = +3
}
#endif
