#version 450
// EXERCISE — this file shadows the preset's volume.geom for shadows/stencil-shadow-volumes only.
//     passlab run   presets/shadows/stencil-shadow-volumes --exercise presets/shadows/stencil-shadow-volumes/exercise
//     passlab grade presets/shadows/stencil-shadow-volumes --exercise presets/shadows/stencil-shadow-volumes/exercise
// As shipped the geometry shader emits no volume: nothing is shadowed.
// Shadow volume of one closed mesh, built in the geometry shader from triangles with adjacency
// (004_9a40ad89bdfc582a.txt L875-878: "input = one complete primitive (optionally with
// adjacency) ... silhouette extrusion for shadow volumes"; 000_c9f7e5de708ecbb3.txt L232-233).
//
// The volume is a closed polyhedron of three sets of polygons (000 L4811-4819):
//   light cap  the triangles facing the light, as they are;
//   dark cap   the same triangles projected to infinity away from the light, w = 0 (L4816-4817);
//   sides      the silhouette edges extruded to infinity (L4818-4826): an edge is on the
//              silhouette when the triangle on one side faces the light and the one across does
//              not (L4823), so each side is emitted once, by its light-facing triangle.
// A point at infinity in direction e is the homogeneous point (e, 0); with the infinite far
// plane (`far = inf`) it projects to depth 1 exactly, inside the clip volume, so the volume is
// never clipped at the far plane (z-fail needs its dark cap).
//
// The light is homogeneous, L = (l, w): w = 1 a point light at l, w = 0 a directional light
// towards l. The direction from the light through p is  e(p) = w p - l  (p - l, or -l).
// Every polygon is wound so its front face points out of the volume: the counting of 000
// L4829-4835 (front faces +1, back faces -1) depends on it.
//
// Vertices 0, 2, 4 are the triangle, 1, 3, 5 the corner opposite each edge across it; an open
// border repeats the triangle's own third corner (host scene::adjacency_indices), which is
// treated as a silhouette so even an open mesh gives a closed volume.
layout(triangles_adjacency) in;
// 3 sides x 4 + light cap 3 + dark cap 3
layout(triangle_strip, max_vertices = 18) out;
layout(location = 0) in vec3 v_world[];

#ifndef SV_CAPS
#define SV_CAPS 1   // z-pass needs no caps (000 L4829-4835); z-fail does (L4808-4809)
#endif

#include "shadows/light_homogeneous.glsl"
vec4 light_h() { return shadow_light_homogeneous(); }

// The triangle (a, b, c) faces the light when its normal points to the light's side of it.
bool faces_light(vec3 a, vec3 b, vec3 c) {
    vec4 L = light_h();
    vec3 to_light = L.xyz - L.w * a;
    return dot(cross(b - a, c - a), to_light) > 0.0;
}

// Depth push of the light cap: 1e-6 in depth is ~0.4 mm at the default view's 6 m with near
// 0.1 (d(depth)/dz = near / z^2 for the infinite projection).
const float kCapPush = 1e-6;

vec4 clip_point(vec3 p) { return frame.view_proj * vec4(p, 1.0); }
// TODO 1 (000_c9f7e5de708ecbb3.txt L4816-4817, "projected to infinity (with w = 0)"): the clip
// position of the point at infinity seen from the light through p: the homogeneous point
// (e(p), 0) with e(p) = L.w p - L.xyz, through frame.view_proj.
vec4 clip_infinity(vec3 p) { return clip_point(p); }

void main() {
    vec3 p[6];
    for (int i = 0; i < 6; ++i) p[i] = v_world[i];
    if (!faces_light(p[0], p[2], p[4])) return;
    // Sides: edge (a, b) of this light-facing triangle is a silhouette when the triangle across,
    // (b, a, o) in its own winding, does not face the light. The strip a, a_inf, b, b_inf faces
    // out of the volume (the triangle's interior lies left of a -> b seen from the light).
    for (int e = 0; e < 3; ++e) {
        vec3 a = p[2 * e], o = p[2 * e + 1], b = p[(2 * e + 2) % 6], own = p[(2 * e + 4) % 6];
        // TODO 2 (000 L4821-4826, "edge shared by front + back face is on silhouette; extrude
        // silhouette edges away from light source"): skip the edge unless the triangle across,
        // (b, a, o) in its own winding, does NOT face the light (an open border, o == own,
        // counts as a silhouette). Then emit the side as one strip of 4 vertices, the edge's two
        // points and their points at infinity, wound so that its front face points OUT of the
        // volume (the counting of L4833-4834 adds +1 for front faces, -1 for back faces).
    }
#if SV_CAPS
    // Light cap: the triangle itself, facing out of the volume towards the light. It lies on the
    // caster's own lit surface, where the scene pass wrote depth, and z-fail must count it as
    // behind that surface (depth test fails), or every lit caster pixel counts +1. The same
    // clip position from a pipeline with a geometry shader is not bit-identical on every
    // driver (lavapipe: speckles on the ball), so the cap is pushed back by kCapPush in depth.
    for (int k = 0; k < 3; ++k) {
        vec4 c = gl_in[2 * k].gl_Position;
        gl_Position = vec4(c.xy, c.z + kCapPush * c.w, c.w); EmitVertex();
    }
    EndPrimitive();
    // Dark cap: the triangle at infinity, wound the other way (it faces away from the light).
    // For a directional light its three corners are one point (the volume closes at a single
    // point at infinity) and it rasterises nothing.
    gl_Position = clip_infinity(p[0]); EmitVertex();
    gl_Position = clip_infinity(p[4]); EmitVertex();
    gl_Position = clip_infinity(p[2]); EmitVertex();
    EndPrimitive();
#endif
}
