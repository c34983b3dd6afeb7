#version 450
// The result, the sharp input, or the velocity (x red, y green, 0.5 = still; 16 px per unit).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D blurred;
uniform sampler2D color;
uniform sampler2D velocity;
void main() {
    vec3 c = params.show == SHOW_SHARP      ? texture(color, uv).rgb
             : params.show == SHOW_VELOCITY ? vec3(0.5 + texture(velocity, uv).xy / 32.0, 0.5)
                                            : texture(blurred, uv).rgb;
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
