// The anti-aliasing presets' test scene, as data both a draw pass (one vertex per
// gl_VertexIndex) and a fragment shader (inside tests, for supersampled references) can use.
// Triangles in uv space ((0,0) top-left, (1,1) bottom-right) so the scene is the same at every
// resolution. Scene 0: shapes; 1: one half-plane-like triangle whose long edge runs from
// (0.3172, -0.2) to (0.6889, 1.2), a steep edge no pixel row lines up with; 2: a quad over the
// whole view, for texture (shading) aliasing without any geometric edge.
#ifndef PASSLAB_AA_SHAPES_GLSL
#define PASSLAB_AA_SHAPES_GLSL

const int kShapeTriangles = 8;

// Vertex v (0..2) of triangle t, and the triangle's colour. scene 0: shapes, 1: edge.
vec2 shape_vertex(int scene, int t, int v) {
    if (scene == 1) {
        const vec2 e[3] = vec2[](vec2(0.3172, -0.2), vec2(0.6889, 1.2), vec2(-1.0, 0.5));
        return t == 0 ? e[v] : vec2(0.0);  // other triangles degenerate
    }
    if (scene == 2) {
        const vec2 f[6] = vec2[](vec2(-0.1, -0.1), vec2(1.1, -0.1), vec2(1.1, 1.1), vec2(-0.1, -0.1), vec2(1.1, 1.1), vec2(-0.1, 1.1));
        return t < 2 ? f[t * 3 + v] : vec2(0.0);
    }
    if (t < 2) {  // a square turned by 17 degrees
        const vec2 q[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, 1));
        const int idx[6] = int[](0, 1, 2, 0, 2, 3);
        float a = radians(17.0);
        vec2 p = q[idx[t * 3 + v]] * 0.22;
        return vec2(0.3, 0.5) + vec2(cos(a) * p.x - sin(a) * p.y, sin(a) * p.x + cos(a) * p.y) * vec2(0.5625, 1.0);
    }
    // A fan of thin slivers around (0.72, 0.5).
    float a0 = float(t - 2) * 0.52, a1 = a0 + 0.06;
    vec2 c = vec2(0.72, 0.5);
    vec2 p = v == 0 ? c : c + 0.4 * vec2(cos(v == 1 ? a0 : a1) * 0.5625, sin(v == 1 ? a0 : a1));
    return p;
}

vec3 shape_color(int scene, int t) {
    if (scene != 0) return vec3(1.0);
    return t < 2 ? vec3(0.95, 0.75, 0.3) : vec3(0.35, 0.75, 1.0);
}

float edge_fn(vec2 a, vec2 b, vec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// How far the square (triangles 0 and 1 of scene 0) has moved: presets that animate it pass
// its offset; 0 elsewhere.
vec2 shape_offset(int scene, int t, vec2 square_offset) { return scene == 0 && t < 2 ? square_offset : vec2(0.0); }

// The colour at uv (the last triangle containing it wins, as in draw order); black outside.
vec3 shape_color_at(int scene, vec2 uv, vec2 square_offset) {
    vec3 c = vec3(0.0);
    for (int t = 0; t < kShapeTriangles; ++t) {
        vec2 o = shape_offset(scene, t, square_offset);
        vec2 a = shape_vertex(scene, t, 0) + o, b = shape_vertex(scene, t, 1) + o, d = shape_vertex(scene, t, 2) + o;
        float e0 = edge_fn(a, b, uv), e1 = edge_fn(b, d, uv), e2 = edge_fn(d, a, uv);
        bool inside = (e0 >= 0.0 && e1 >= 0.0 && e2 >= 0.0) || (e0 <= 0.0 && e1 <= 0.0 && e2 <= 0.0);
        float area = edge_fn(a, b, d);
        if (inside && abs(area) > 0.0) c = shape_color(scene, t);
    }
    return c;
}
// The same test for many samples of one pixel (supersampled references): shape_triangles
// evaluates the vertices once (shape_vertex's cos/sin per vertex would otherwise run per
// sample), shape_color_in the loop of shape_color_at on them: the same operations on the same
// values, so the same colour as shape_color_at(scene, uv, square_offset) bit for bit.
void shape_triangles(int scene, vec2 square_offset, out vec2 tri[kShapeTriangles * 3], out bool solid[kShapeTriangles]) {
    for (int t = 0; t < kShapeTriangles; ++t) {
        vec2 o = shape_offset(scene, t, square_offset);
        for (int v = 0; v < 3; ++v) tri[t * 3 + v] = shape_vertex(scene, t, v) + o;
        solid[t] = abs(edge_fn(tri[t * 3], tri[t * 3 + 1], tri[t * 3 + 2])) > 0.0;
    }
}
vec3 shape_color_in(int scene, const vec2 tri[kShapeTriangles * 3], const bool solid[kShapeTriangles], vec2 uv) {
    vec3 c = vec3(0.0);
    for (int t = 0; t < kShapeTriangles; ++t) {
        vec2 a = tri[t * 3], b = tri[t * 3 + 1], d = tri[t * 3 + 2];
        float e0 = edge_fn(a, b, uv), e1 = edge_fn(b, d, uv), e2 = edge_fn(d, a, uv);
        bool inside = (e0 >= 0.0 && e1 >= 0.0 && e2 >= 0.0) || (e0 <= 0.0 && e1 <= 0.0 && e2 <= 0.0);
        if (inside && solid[t]) c = shape_color(scene, t);
    }
    return c;
}

// Scene 2's texture: a fine procedural checker (about 1.3 cells per pixel at 640 px, well above
// what the pixel grid can carry), shaded per fragment: aliasing no extra coverage sample fixes.
vec3 shape_texture(vec2 uv) {
    vec2 c = floor(uv * vec2(830.0, 470.0) + 0.37 * uv.y * 300.0);
    return vec3(mod(c.x + c.y, 2.0));
}
#endif
