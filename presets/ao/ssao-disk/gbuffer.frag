#version 450
// The G-buffer method 2 needs (004_9a40ad89bdfc582a.txt L729: "re-project every pixel to
// the 3D point, in camera space"): view-space position and normal.
// Scene "probe" (tests): one pixel of the plane, params.blocker_offset pixels right of the centre,
// stores its point raised by params.blocker_height along the normal — a single sample disk
// in front of the plane at a known place, the rest of the plane flat.
layout(location = 0) in vec3 v_view_pos;
layout(location = 1) in vec3 v_view_normal;
layout(location = 0) out vec4 normal;
layout(location = 1) out vec4 vpos;
void main() {
    vec3 n = normalize(v_view_normal);
    if (dot(n, -v_view_pos) < 0.0) n = -n;  // two-sided walls: the side facing the eye
    vec3 p = v_view_pos;
    if (params.scene == SCENE_PROBE && ivec2(gl_FragCoord.xy) == ivec2(frame.resolution.xy) / 2 + ivec2(params.blocker_offset, 0))
        p += params.blocker_height * n;
    normal = vec4(n, 1.0);
    vpos = vec4(p, 1.0);
}
