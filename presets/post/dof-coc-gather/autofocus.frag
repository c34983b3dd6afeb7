#version 450
// 002_644d46bdce7e5305.txt L1254-1270: the focal plane follows the scene,
//   F = mix(F_prev, sum / weight (or 4096 if nothing), speed)
// here the mean linear depth of a small window at the centre; or the manual focus.
layout(location = 0) out float focus_state;
uniform sampler2D depth;
uniform sampler2D focus_state_prev;
const float kNear = 0.1, kFar = 100.0;
float linear_z(float d) { return kNear * kFar / (kFar - d * (kFar - kNear)); }
void main() {
    if (!params.autofocus) {
        focus_state = params.focus;
        return;
    }
    ivec2 c = textureSize(depth, 0) / 2;
    float sum = 0.0, weight = 0.0;
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x) sum += linear_z(texelFetch(depth, c + ivec2(x, y) * 4, 0).r), weight += 1.0;
    float target = weight > 1e-5 ? sum / weight : 4096.0;
    float prev = texelFetch(focus_state_prev, ivec2(0), 0).r;
    focus_state = frame.index == 0 ? target : mix(prev, target, params.speed);
}
