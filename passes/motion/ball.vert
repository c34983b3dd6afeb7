#version 450
// A ball for the motion-blur presets: it moves along x at params.speed and wraps around every
// 6 units. Its previous position
// is this one minus one frame of motion, speed * delta, never the wrapped value: a wrap is a
// teleport, not motion, and must not smear across the screen.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec4 v_clip_now;
layout(location = 2) out vec4 v_clip_prev;
layout(location = 3) out float v_view_depth;  // distance along the view axis, for depth-aware blurs

const float kTrack = 6.0;  // x range [-3, 3] the ball loops over

void main() {
    float x = mod(params.speed * frame.time + 0.5 * kTrack, kTrack) - 0.5 * kTrack;
    vec3 now = position + vec3(x, 0.0, 0.0);
    vec3 prev = now - vec3(params.speed * frame.delta, 0.0, 0.0);
    v_normal = normal;
    v_clip_now = frame.view_proj * vec4(now, 1.0);
    // Last frame's camera too: camera motion adds to object motion.
    v_clip_prev = frame.prev_view_proj * vec4(prev, 1.0);
    v_view_depth = -(frame.view * vec4(now, 1.0)).z;
    gl_Position = v_clip_now;
}
