// Shared by show.vert and delta.comp: where the meshes stand. The floor planes are lowered to
// FLOOR_Y, so their plane equation has D != 0 and a sign error in D shows (a plane through the
// origin would hide it).
#define FLOOR_Y (-0.02)
vec3 place(vec3 p, bool floor_plane) { return floor_plane ? p + vec3(0.0, FLOOR_Y, 0.0) : p; }
