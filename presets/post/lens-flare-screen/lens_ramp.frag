#version 450
// The lens colour ramp (002 L828-830 and L940-941 sample it by the normalised distance from the centre):
// a procedural spectrum-like ramp, warm at the centre, through green to blue at the rim, in the
// spirit of the 64k intro's texture the talk shows (not its exact data).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ramp;
void main() {
    float t = uv.x;
    vec3 c = 0.5 + 0.5 * cos(6.28318 * (t * 0.8 + vec3(0.0, 0.33, 0.67)));
    ramp = vec4(c, 1.0);
}
