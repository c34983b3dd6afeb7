// The test scene's instances and rays, shared by every pass of the graph so that they trace
// exactly the same rays. Meshes are indices in the buffers' `meshes` = [teapot, floor, box].
#include "common/hash.glsl"
#include "raytrace/bvh.glsl"

const int INSTANCE_COUNT = 5;
const uint MESH_TEAPOT = 0u, MESH_FLOOR = 1u, MESH_BOX = 2u;

// The teapot generator centres its bounding box: its base is 0.4828 below the origin (the
// lowest point of the body, 1.575 * 2 / 6.525, see host/scene/teapot.cpp).
const float TEAPOT_BASE = 0.4828;

struct Placement {
    uint mesh;
    vec3 offset;  // world position of the object origin
    float yaw;    // rotation about +y, radians
    float scale;  // uniform
};

Placement placement(int i) {
    if (i == 0) return Placement(MESH_TEAPOT, vec3(0.0, TEAPOT_BASE, 0.0), 0.0, 1.0);
    if (i == 1) return Placement(MESH_TEAPOT, vec3(1.6, 0.5 * TEAPOT_BASE, -0.8), 1.5707963, 0.5);
    if (i == 2) return Placement(MESH_FLOOR, vec3(0.0), 0.0, 1.0);
    if (i == 3) return Placement(MESH_BOX, vec3(-1.5, 0.5, 0.5), 0.0, 1.0);
    return Placement(MESH_BOX, vec3(0.5, 0.3, 1.5), 0.7853982, 0.6);
}

// Inverse of world = offset + scale * R_y(yaw) * object: object = R_y(-yaw) (world - offset) / scale.
mat4 object_from_world(Placement p) {
    float c = cos(p.yaw), s = sin(p.yaw);
    mat3 r_inv = mat3(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c);  // columns of R_y(-yaw)
    mat3 m = r_inv / p.scale;
    return mat4(vec4(m[0], 0.0), vec4(m[1], 0.0), vec4(m[2], 0.0), vec4(-(m * p.offset), 1.0));
}

// Rays of pixel `px` of the 64 x 80 image: rows 0..63 primary rays of the view camera (the
// 64 x 64 grid), rows 64..78 random origins in [-3, 3] x [0.05, 2] x [-3, 3] with random
// directions (inside boxes, grazing the floor, from below ...), row 79 hand-placed probes.
void ray_of(ivec2 px, out vec3 ro, out vec3 rd) {
    if (px.y < 64) {
        vec2 ndc = (vec2(px) + 0.5) / 64.0 * 2.0 - 1.0;
        vec4 a = frame.inv_view_proj * vec4(ndc, 0.0, 1.0), b = frame.inv_view_proj * vec4(ndc, 1.0, 1.0);
        ro = frame.camera_pos.xyz;
        rd = normalize(b.xyz / b.w - a.xyz / a.w);
        return;
    }
    if (px.y == 79 && px.x < 8) {
        // t by hand: straight down onto the floor from y = 5 (t = 5); straight up (miss); along
        // -z onto box 3's face z = 1 from z = 5 (t = 4); from inside box 3 to its face x = -1
        // (t = 0.5, a back face); down onto box 4's top y = 0.3 + 0.6 / 2 from y = 5 (t = 4.4: on a
        // scaled instance t is still the world parameter); down onto teapot 0's lid (no t by
        // hand); a ray grazing the floor at y = 1e-3; the floor from below (two-sided: t = 1).
        // Every probe avoids the diagonals of the quads it hits.
        const vec3 o[8] = vec3[](vec3(3.3, 5.0, 2.9), vec3(0.0, 5.0, 0.0), vec3(-1.3, 0.6, 5.0), vec3(-1.5, 0.6, 0.3),
                                 vec3(0.6, 5.0, 1.55), vec3(0.05, 3.0, 0.03), vec3(-4.9, 0.001, -3.7), vec3(2.7, -1.0, -3.1));
        const vec3 d[8] = vec3[](vec3(0, -1, 0), vec3(0, 1, 0), vec3(0, 0, -1), vec3(1, 0, 0),
                                 vec3(0, -1, 0), vec3(0, -1, 0), normalize(vec3(1.0, 0.0, 0.37)), vec3(0, 1, 0));
        ro = o[px.x];
        rd = d[px.x];
        return;
    }
    vec3 h = hash_pcg3(vec3(px, 17.0)), g = hash_pcg3(vec3(px, 91.0));
    ro = vec3(-3.0, 0.05, -3.0) + h * vec3(6.0, 1.95, 6.0);
    // Uniform direction on the sphere (Archimedes: z uniform in [-1, 1], azimuth uniform).
    float z = g.x * 2.0 - 1.0, phi = 6.2831853 * g.y;
    rd = vec3(sqrt(1.0 - z * z) * vec2(cos(phi), sin(phi)), z);
}
