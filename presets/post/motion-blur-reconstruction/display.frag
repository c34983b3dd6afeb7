#version 450
// The result, the sharp input, V, or NeighbourMax (x red, y green, 0.5 = still; 32 px per unit).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D result;
uniform sampler2D color;
uniform sampler2D vq;
uniform sampler2D neighbourmax;
void main() {
    vec3 c = params.show == SHOW_SHARP          ? texture(color, uv).rgb
             : params.show == SHOW_VELOCITY     ? vec3(0.5 + texture(vq, uv).xy / 64.0, 0.5)
             : params.show == SHOW_NEIGHBOURMAX ? vec3(0.5 + texture(neighbourmax, uv).xy / 64.0, 0.5)
                                                : texture(result, uv).rgb;
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
