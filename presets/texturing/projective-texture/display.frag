#version 450
// Tone map (clamp) and mark the projector's position with a small yellow dot.
#include "projector.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D hdr;
void main() {
    vec3 c = clamp(texture(hdr, uv).rgb, 0.0, 1.0);
    vec4 clip = frame.view_proj * vec4(params.proj_pos, 1.0);
    vec2 at = (clip.xy / clip.w * 0.5 + 0.5) * frame.resolution.xy;
    if (clip.w > 0.0 && distance(at, uv * frame.resolution.xy) < 3.0) c = vec3(1.0, 0.85, 0.2);
    color = vec4(c, 1.0);
}
