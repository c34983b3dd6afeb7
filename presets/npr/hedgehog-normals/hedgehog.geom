#version 450
// Pass 2, the hedgehog plot (004_9a40ad89bdfc582a.txt L1157; the two-pass scheme of L1144-1151:
// "render geometry again, input of the geometry shader = triangles, output = lines"): each
// triangle becomes up to three line segments, one per corner, from the vertex p along its unit
// normal to p + scale n — or, with mode = face, one segment from the centroid along the
// triangle's geometric normal. The normal is normalised *here*, after the model transform's
// inverse transpose (object.vert): with a non-uniform scale the interpolated or transformed
// normal is no longer unit length, and the line would not be `scale` long.
// A vertex shared by k triangles is emitted k times (the same segment drawn again): the price of
// triangle input; a point-list draw would emit each index once per reference too.
layout(triangles) in;
layout(line_strip, max_vertices = 6) out;
layout(location = 0) in vec3 v_world[];
layout(location = 1) in vec3 v_normal[];
layout(location = 0) out vec3 g_color;

void segment(vec3 p, vec3 n) {
    g_color = 0.5 + 0.5 * n;  // the direction as a colour
    gl_Position = frame.view_proj * vec4(p, 1.0);
    EmitVertex();
    gl_Position = frame.view_proj * vec4(p + params.scale * n, 1.0);
    EmitVertex();
    EndPrimitive();
}

void main() {
    // A mesh hidden by its vertex shader (every vertex at one clip point) emits nothing.
    if (gl_in[0].gl_Position == gl_in[1].gl_Position && gl_in[1].gl_Position == gl_in[2].gl_Position) return;
    if (params.mode == MODE_FACE) {
        vec3 n = cross(v_world[1] - v_world[0], v_world[2] - v_world[0]);
        if (dot(n, n) > 0.0) segment((v_world[0] + v_world[1] + v_world[2]) / 3.0, normalize(n));
        return;
    }
    for (int i = 0; i < 3; ++i) segment(v_world[i], normalize(v_normal[i]));
}
