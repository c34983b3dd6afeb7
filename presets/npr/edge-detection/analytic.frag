#version 450
// Analytic depth buffers D the operators are tested on (x = pixel centre in pixels):
//   constant  D = 2
//   ramp      D = 2 + 0.001 x
//   step      D = 2 for x < 32, 3 from there
//   crease    D = 2 + 0.001 |x - 32|
//   ramp_xy   D = 2 + 0.001 x + 0.002 y   (y = pixel row centre: the operators' vertical halves)
//   step_y    D = 2 for y < 32, 3 from there
// with normals of 45 degree flanks where D slopes (n = normalize(+-1, 0, 1)), (0, 0, 1) where it
// is flat. For the rendered objects this pass only clears: D = 0 (1 / infinity), normal w = 0.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 normal;
layout(location = 1) out float inv_depth;


void main() {
    float x = gl_FragCoord.x, y = gl_FragCoord.y, d = 2.0, flank = 0.0;  // flank: -1, 0, +1 (45 degrees left/right)
    if (params.scene == SCENE_OBJECTS) {
        normal = vec4(0.0, 0.0, 1.0, 0.0);
        inv_depth = 0.0;
        return;
    } else if (params.scene == SCENE_RAMP) {
        d = 2.0 + 0.001 * x, flank = 1.0;
    } else if (params.scene == SCENE_STEP) {
        d = x < 32.0 ? 2.0 : 3.0;
    } else if (params.scene == SCENE_CREASE) {
        d = 2.0 + 0.001 * abs(x - 32.0), flank = sign(x - 32.0);
    } else if (params.scene == SCENE_RAMP_XY) {
        d = 2.0 + 0.001 * x + 0.002 * y, flank = 1.0;
    } else if (params.scene == SCENE_STEP_Y) {
        d = y < 32.0 ? 2.0 : 3.0;
    }
    normal = vec4(normalize(vec3(flank, 0.0, 1.0)), 1.0);
    inv_depth = d;
}
