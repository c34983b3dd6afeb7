#version 450
// EXERCISE — this file shadows the preset's shrink.geom (TODO 3-4; TODO 1-2 are in
// point_to_triangle.geom). The face shading and project() are done for you.
// Shrinking triangles (004_9a40ad89bdfc582a.txt L1044-1046): every triangle is scaled about
// its centroid c by the factor s, corner by corner,  p' = c + s (p - c),  before projection.
// Scaling a triangle by s scales its area by s^2; the projection is affine for the flat test
// (FLAT) so the projected area scales by s^2 too (under perspective only approximately).
// All varyings must pass through the geometry shader (004 L960): the face normal is made here.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
layout(location = 0) in vec3 v_world[];
layout(location = 0) out vec3 g_color;

// FLAT: the plane y = 0 seen straight from above, x and z times kFlatScale in NDC (an
// orthographic projection written out, so the test's area is exact). Otherwise the view
// camera; in the split view the mesh takes the right half: a half-width viewport doubles
// x_ndc (aspect / 2) and maps it to [0, 1], x' = (2 x) / 2 + 1/2 = x + w/2 in clip space.
// params.turn rotates the plane in the view (degrees): at 0 every triangle has the same
// sub-pixel position, so their rasterisation errors add up instead of cancelling (s = 0.8:
// 171 pixels for an area of 184.3, -7.2% on every triangle); turned, they decorrelate.
const float kFlatScale = 0.75;
vec4 project(vec3 p) {
#ifdef FLAT
    float a = radians(params.turn);
    vec2 q = mat2(cos(a), sin(a), -sin(a), cos(a)) * p.xz;
    return vec4(q * kFlatScale, 0.5, 1.0);
#else
    vec4 c = frame.view_proj * vec4(p, 1.0);
    if (params.mode == MODE_SPLIT) c.x += 0.5 * c.w;
    return c;
#endif
}

void main() {
    if (gl_in[0].gl_Position.z < -1.0) return;          // hidden pass (VISIBLE false)
    // TODO 3: c, the triangle's centroid (the point the triangle is shrunk about, L1044-1046).
    vec3 c = (v_world[0] + v_world[1] + v_world[2]) / 3.0;
    vec3 n = normalize(cross(v_world[1] - v_world[0], v_world[2] - v_world[0]));
    vec3 l = normalize(vec3(0.4, 0.8, 0.5));
    vec3 base = FLAT_COLOR;
    vec3 shade = base * (0.04 + 0.96 * max(dot(n, l), 0.0));   // Lambert per face, a little ambient
    // TODO 4: emit the shrunk triangle: corner i moved to p' = c + s (p_i - c), s = params.shrink,
    // then projected with project(); the corners in an order that keeps the input's winding (the
    // sphere pass culls back faces: the rasterizer decides front and back from the emitted order).
    // As shipped the corners go out unshrunk.
    for (int i = 2; i >= 0; --i) {   // MISTAKE: corners emitted in reverse order
        gl_Position = project(c + params.shrink * (v_world[i] - c));
        g_color = shade;
        EmitVertex();
    }
    EndPrimitive();
}
