#version 450
// The motion-blur presets' static backdrop, a plane at z = -1 behind the ball: each pixel's ray (unprojected through this frame's
// inverse view-projection) meets it at p, whose velocity is p through this frame's and last
// frame's view-projection. A fixed camera gives zero; orbiting gives camera-motion blur.
#include "velocity.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 velocity;

const float kPlaneZ = -1.0;
const float kCells = 4.0;  // checker cells per unit

void main() {
    vec2 ndc = uv * 2.0 - 1.0;
    vec4 a = frame.inv_view_proj * vec4(ndc, 0.0, 1.0), b = frame.inv_view_proj * vec4(ndc, 1.0, 1.0);
    vec3 o = a.xyz / a.w, d = b.xyz / b.w - o;
    float t = abs(d.z) > 1e-6 ? (kPlaneZ - o.z) / d.z : 0.0;
    vec3 p = o + t * d;
    vec2 cell = floor(p.xy * kCells);
    float checker = mod(cell.x + cell.y, 2.0);
    color = params.backdrop == BACKDROP_BLACK ? vec4(0.0, 0.0, 0.0, 1.0) : vec4(vec3(0.1 + 0.3 * checker), 1.0);
    velocity = vec4(velocity_pixels(frame.view_proj * vec4(p, 1.0), frame.prev_view_proj * vec4(p, 1.0)),
                    -(frame.view * vec4(p, 1.0)).z, 1.0);  // xy pixels per frame, z view depth
}
