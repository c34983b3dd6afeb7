#version 450
// The picture of the trace: shaded = a colour per instance lit by a head light, with the normal
// rebuilt from the hit positions of neighbouring pixels (the hit records carry no normal: the
// cross product of the position's differences along x and y, each taken towards the neighbour on
// the same instance and nearer in depth); cost = the traversal's work per ray as a heat ramp.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D hits;
uniform sampler2D pos;

vec4 at(ivec2 p) { return texelFetch(pos, clamp(p, ivec2(0), textureSize(pos, 0) - 1), 0); }

// The difference towards the neighbour (left or right, down or up) on the same instance with the
// smaller step: no normal is made across a silhouette.
vec3 diff(ivec2 px, ivec2 step, vec4 c) {
    vec4 a = at(px + step), b = at(px - step);
    vec3 da = a.w == c.w ? a.xyz - c.xyz : vec3(1e9), db = b.w == c.w ? c.xyz - b.xyz : vec3(1e9);
    return dot(da, da) < dot(db, db) ? da : db;
}

void main() {
    ivec2 px = ivec2(uv * vec2(textureSize(hits, 0)));
    vec4 h = texelFetch(hits, px, 0), c = at(px);
    if (params.view_mode == VIEW_MODE_COST) {
        // 0 .. 200 units of work: blue -> green -> red
        float w = clamp(h.w / 200.0, 0.0, 1.0);
        color = vec4(clamp(vec3(2.0 * w - 1.0, 1.0 - abs(2.0 * w - 1.0), 1.0 - 2.0 * w), 0.0, 1.0), 1.0);
        return;
    }
    if (h.x < 0.0) {
        color = vec4(0.05, 0.06, 0.12, 1.0);
        return;
    }
    vec3 n = normalize(cross(diff(px, ivec2(1, 0), c), diff(px, ivec2(0, 1), c)));
    vec3 to_eye = normalize(frame.camera_pos.xyz - c.xyz);
    vec3 albedo = h.x < 0.5 ? vec3(0.85, 0.55, 0.25) : vec3(0.55, 0.6, 0.65);
    color = vec4(albedo * (0.15 + 0.85 * abs(dot(n, to_eye))), 1.0);
}
