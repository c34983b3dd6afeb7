#version 450
// Subdivision in the geometry shader (000_c9f7e5de708ecbb3.txt L5939-5945: "curved surface
// defined by repeated subdivision steps on a polygonal model ... compute in geometry shader").
// Each of `levels` steps splits every triangle into 4 at its edge midpoints, so one input
// triangle becomes 4^L: a barycentric grid of N = 2^L steps per edge, emitted as N strips
// (row r has 2r + 1 triangles; sum over r of 2r + 1 = N^2 = 4^L).
//
// The new vertices are placed on the PN triangle (curved point-normal triangle; Vlachos et al.
// 2001, not in the seeds) of the corners P_i and normals N_i: a cubic Bezier patch whose edge
// control points are the edge third-points projected onto the corners' tangent planes,
//     b210 = (2 P1 + P2 - w12 N1) / 3,   w_ij = (P_j - P_i) . N_i,
// and whose centre is b111 = E + (E - V) / 2 (E: mean of the six edge points, V: of the corners).
// On a planar patch every N_i is the plane's normal, so w_ij = 0, every control point is an
// affine combination of the corners and the patch is the flat triangle itself: subdividing a
// plane changes nothing (the test planar-unchanged). Normals are interpolated linearly.
//
// Every emitted triangle is counted with atomics (the test triangles-x4-per-level):
//   sub.total += 1,  sub.per_input[gl_PrimitiveIDIn] += 1  (= 4^L for every input triangle).
layout(triangles) in;
// N = 8 (3 levels): N^2 + 2N = 80 vertices of 9 components, within lavapipe's 1024 in all.
layout(triangle_strip, max_vertices = 80) out;
layout(location = 0) in vec3 v_world[];
layout(location = 1) in vec3 v_normal[];
layout(location = 0) out vec3 g_normal;
layout(location = 1) out vec2 g_bary;     // 2 of the 3 sub-triangle barycentrics (wireframe); 3 would exceed 1024
layout(std430) buffer Sub { uint total; uint per_input[]; } sub;
#ifdef SPHERE_RADIUS
// Test instrument for the sphere (centre OFFSET, radius SPHERE_RADIUS): the largest distance
// from the sphere of an emitted vertex on the PN patch and, for comparison, of the same vertex on
// the flat triangle (what subdivision without a surface rule would produce). Non-negative floats
// order like their bits, so atomicMax on the bits is a float max.
layout(std430) buffer Radial { uint pn_max; uint linear_max; } radial;
#endif

vec3 b300, b030, b003, b210, b120, b021, b012, b201, b102, b111;

// The control point of edge P_i -> P_j nearer P_i.
vec3 edge_point(vec3 pi, vec3 pj, vec3 ni) {
    float w = dot(pj - pi, ni);
    return (2.0 * pi + pj - w * ni) / 3.0;
}

void pn_setup() {
    vec3 p1 = v_world[0], p2 = v_world[1], p3 = v_world[2];
    vec3 n1 = normalize(v_normal[0]), n2 = normalize(v_normal[1]), n3 = normalize(v_normal[2]);
    b300 = p1; b030 = p2; b003 = p3;
    b210 = edge_point(p1, p2, n1); b120 = edge_point(p2, p1, n2);
    b021 = edge_point(p2, p3, n2); b012 = edge_point(p3, p2, n3);
    b102 = edge_point(p3, p1, n3); b201 = edge_point(p1, p3, n1);
    vec3 e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
    vec3 v = (p1 + p2 + p3) / 3.0;
    b111 = e + (e - v) / 2.0;
}

// The cubic patch at barycentrics (w, u, v) of (P1, P2, P3).
vec3 pn_point(vec3 b) {
    float w = b.x, u = b.y, v = b.z;
    return b300 * w * w * w + b030 * u * u * u + b003 * v * v * v
         + b210 * 3.0 * w * w * u + b120 * 3.0 * w * u * u + b201 * 3.0 * w * w * v
         + b021 * 3.0 * u * u * v + b102 * 3.0 * w * v * v + b012 * 3.0 * u * v * v
         + b111 * 6.0 * w * u * v;
}

// Grid point k of row r (r = 0 at P1): weights (1 - r/N, k/N, (r - k)/N). Row order keeps the
// strip's first triangle (P(r+1,0), P(r,0), P(r+1,1)) wound like (P1, P2, P3).
void emit(int r, int k, float n, int j) {
    vec3 b = vec3(1.0 - float(r) / n, float(k) / n, float(r - k) / n);
    vec3 p = pn_point(b);
#ifdef SPHERE_RADIUS
    if (params.verify) {   // test-only: two atomics per vertex
        vec3 flat_p = b.x * b300 + b.y * b030 + b.z * b003;
        atomicMax(radial.pn_max, floatBitsToUint(abs(length(p - OFFSET) - SPHERE_RADIUS)));
        atomicMax(radial.linear_max, floatBitsToUint(abs(length(flat_p - OFFSET) - SPHERE_RADIUS)));
    }
#endif
    gl_Position = frame.view_proj * vec4(p, 1.0);
    g_normal = b.x * v_normal[0] + b.y * v_normal[1] + b.z * v_normal[2];
    // Strip vertex j is corner j mod 3 of every triangle it is in: the three differ in each
    // triangle, so a component near 0 marks a sub-triangle edge (the wireframe).
    int c = j % 3;
    g_bary = vec2(c == 0, c == 1);
    EmitVertex();
}

void count_triangle() {
    atomicAdd(sub.total, 1u);
    atomicAdd(sub.per_input[gl_PrimitiveIDIn], 1u);
}

void main() {
    pn_setup();
    int levels = LEVELS;
    int n = 1 << levels;
    for (int r = 0; r < n; ++r) {
        // 2r + 3 vertices: bottom/top alternately; a triangle completes at every vertex from the third on.
        for (int k = 0; k <= r; ++k) {
            emit(r + 1, k, float(n), 2 * k);
            if (k > 0) count_triangle();
            emit(r, k, float(n), 2 * k + 1);
            if (k > 0) count_triangle();
        }
        emit(r + 1, r + 1, float(n), 2 * r + 2);
        count_triangle();
        EndPrimitive();
    }
}
