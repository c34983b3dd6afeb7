#version 450
// The default stage (show = taa) from the half-resolution working image to the view: its own
// pass so the live view does not pay for display.frag's branch over the other stages (issue #21).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D taa;
void main() {
    ldr = vec4(clamp(texture(taa, uv).rgb, 0.0, 1.0), 1.0);
}
