#version 450
// The scene mesh (scene.obj: precomputed-ao's patches), drawn from the view camera. CULL = 1: the
// live G-buffer, culling triangles gbuffer.frag would discard entirely; 0: every triangle (the
// test-only check that the cull drops nothing).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;  // uv.x = patch id (make_scene.py)
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out float v_id;

// The longest edge of any triangle of scene.obj (the floor's diagonals, 6/48 * sqrt(2) = 0.177),
// rounded up: the cull below is safe with any bound at least this.
const float kMaxEdge = 0.2;

void main() {
    v_world = position;
    v_normal = normal;
    v_id = uv.x;
    gl_Position = frame.view_proj * vec4(position, 1.0);
    // gbuffer.frag discards every fragment whose interpolated normal faces away from the eye, so
    // a triangle all of whose fragments it would discard need not be rasterised at all (issue
    // #21: about half the triangles, the far sides of the balls, box and bowl sheets). At a
    // fragment with barycentrics b_i (sum 1, >= 0), with unit vertex normals n_i:
    //   n . (e - p) = sum_i b_i n_i . (e - p_i)  +  sum_ij b_i b_j n_i . (p_i - p_j),
    // the second sum within +-(the triangle's longest edge). So when every corner has
    // n_i . (e - p_i) < -kMaxEdge, every fragment is discarded: the cull distance below is
    // negative at all three corners exactly then, and the rasteriser drops the triangle. It drops
    // nothing the fragment shader would keep: the G-buffer is the same, bit for bit.
#if CULL
    gl_CullDistance[0] = dot(normal, frame.camera_pos.xyz - position) + kMaxEdge;
#endif
}
