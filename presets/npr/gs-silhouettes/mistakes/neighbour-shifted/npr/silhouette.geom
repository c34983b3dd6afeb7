#version 450
// Silhouette edges in a geometry shader (004_9a40ad89bdfc582a.txt L1138-1155): input triangles
// with adjacency, output lines — "the geometry shader checks whether the triangle contains a
// silhouette edge; if yes, output a line, if no, output no geometry".
//
// Vertices 0, 2, 4 are the triangle; 1, 3, 5 the vertex opposite each edge in the triangle
// across it. An edge is a silhouette when this triangle faces the eye and the one across does
// not:  (n . v > 0) and (n' . v <= tolerance |n'||v|),  v = eye - p (ortho: the view direction).
// Each silhouette edge is therefore emitted once, by its front-facing triangle. Lines are
// emitted as screen-space quads params.width pixels wide (wide lines are optional in Vulkan),
// counted with an atomic in the `edges` buffer.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 12) out;
layout(location = 0) in vec3 v_world[];
layout(std430) buffer edges { uint emitted; };

#include "npr/silhouette.glsl"   // to_eye, faces_eye

// The line is a quad params.width pixels wide laid on the outer side of the edge (away from the
// triangle's third corner c): centred on the edge, its inner half would lie over the surface
// that bulges towards the eye next to the silhouette and fail the depth test.
void emit_edge(vec3 a, vec3 b, vec3 c) {
    vec4 ca = frame.view_proj * vec4(a, 1.0), cb = frame.view_proj * vec4(b, 1.0), cc = frame.view_proj * vec4(c, 1.0);
    vec2 sa = ca.xy / ca.w * frame.resolution.xy, sb = cb.xy / cb.w * frame.resolution.xy;  // pixels x 2
    vec2 sc = cc.xy / cc.w * frame.resolution.xy;
    vec2 dir = sb - sa;
    if (dot(dir, dir) < 1e-12) return;
    vec2 out_dir = normalize(vec2(-dir.y, dir.x));
    if (dot(out_dir, 0.5 * (sa + sb) - sc) < 0.0) out_dir = -out_dir;
    // params.width pixels in NDC (2 units across the view).
    vec2 side = out_dir * 2.0 * params.width / frame.resolution.xy;
    // A small depth pull towards the eye keeps the line in front of what it borders.
    const float kPull = 1e-4;
    gl_Position = vec4(ca.xy, ca.z - kPull * ca.w, ca.w); EmitVertex();
    gl_Position = vec4(ca.xy + side * ca.w, ca.z - kPull * ca.w, ca.w); EmitVertex();
    gl_Position = vec4(cb.xy, cb.z - kPull * cb.w, cb.w); EmitVertex();
    gl_Position = vec4(cb.xy + side * cb.w, cb.z - kPull * cb.w, cb.w); EmitVertex();
    EndPrimitive();
    atomicAdd(emitted, 1u);
}

void main() {
    // A mesh hidden by its vertex shader (every vertex at one clip point) emits nothing.
    if (gl_in[0].gl_Position == gl_in[2].gl_Position && gl_in[2].gl_Position == gl_in[4].gl_Position) return;
    vec3 p[6];
    for (int i = 0; i < 6; ++i) p[i] = v_world[i];
    if (!faces_eye(p[0], p[2], p[4], 0.0)) return;
    // Edge (a, b) with neighbour vertex o: the triangle across is (b, a, o) in its own winding.
    // An open border has no triangle across: the adjacency list then repeats this triangle's
    // own opposite vertex (scene/mesh.hpp), which we recognise and skip.
    for (int e = 0; e < 3; ++e) {
        vec3 a = p[2 * e], o = p[(2 * e + 5) % 6], b = p[(2 * e + 2) % 6], own = p[(2 * e + 4) % 6];
        if (o == own) continue;
        if (!faces_eye(b, a, o, params.tolerance)) emit_edge(a, b, own);
    }
}
