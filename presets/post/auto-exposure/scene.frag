#version 450
// day_night: a room lit through a window whose light switches between bright day (x8) and a
// dim lamp every 4 seconds, so the adaptation is visible in `passlab run`. gradient: luminance
// u (the mean test). step: a flat 1 until t = 0, then 4 (the adaptation test). quadratic:
// luminance u^2 (a mean test whose mean, 1/3, differs from the value at the centre, 1/4).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
void main() {
    if (params.scene == SCENE_GRADIENT) {
        hdr = vec4(vec3(uv.x), 1.0);
    } else if (params.scene == SCENE_QUADRATIC) {
        hdr = vec4(vec3(uv.x * uv.x), 1.0);
    } else if (params.scene == SCENE_STEP) {
        hdr = vec4(vec3(frame.time < 1e-3 ? 1.0 : 4.0), 1.0);  // 1e-3: the test clock lands on 0 only to rounding
    } else {
        float day = mod(frame.time, 8.0) < 4.0 ? 8.0 : 0.25;
        vec3 wall = vec3(0.5, 0.45, 0.4) * (0.3 + 0.7 * smoothstep(1.0, 0.2, abs(uv.x - 0.35)));
        bool window = abs(uv.x - 0.35) < 0.12 && abs(uv.y - 0.4) < 0.2;
        vec3 c = window ? vec3(1.2, 1.3, 1.5) * day : wall * day * 0.4;
        if (uv.y > 0.72) c = vec3(0.3, 0.22, 0.15) * day * 0.3;  // floor
        hdr = vec4(c, 1.0);
    }
}
