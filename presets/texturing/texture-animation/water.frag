#version 450
// Texture animation (000_c9f7e5de708ecbb3.txt L1618-1627): "a texture matrix — can specify an
// arbitrary 4x4 matrix, each frame! Possibilities: moving water or sky"; "custom shader
// programs — can use video as texture".
// The texture matrix M(t) is rebuilt from the time every frame (animation.glsl).
// mode = video: layer floor(t * fps) mod N of the baked frames; water: two noise layers
// scrolled in different directions and multiplied, the classic moving-water trick.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 hdr;
uniform sampler2D pattern;
uniform sampler2D noise;
uniform sampler2DArray frames;

#include "animation.glsl"

void main() {
    float t = animation_time();
    vec3 c;
    if (params.mode == MODE_VIDEO) {
        int n = textureSize(frames, 0).z;
        int k = video_frame(t, params.fps, n);
        c = texture(frames, vec3(v_uv, float(k))).rgb;
    } else if (params.mode == MODE_WATER) {
        vec2 a = (texture_matrix(t, params.scroll, 0.0) * vec3(v_uv, 1.0)).xy;
        vec2 b = (texture_matrix(t, -0.5 * params.scroll.yx, 0.0) * vec3(v_uv * 1.3, 1.0)).xy;
        float h = texture(noise, a).r * texture(noise, b).r;
        c = mix(vec3(0.01, 0.05, 0.12), vec3(0.45, 0.7, 0.85), smoothstep(0.12, 0.55, h));
    } else {
        vec2 st = (texture_matrix(t, params.scroll, params.mode == MODE_ROTATE ? params.spin : 0.0) * vec3(v_uv, 1.0)).xy;
        c = texture(pattern, st).rgb;
    }
    hdr = vec4(c, 1.0);
}
