#version 450
// An evening sky with the sun at params.light (uv) and dark hills, in linear HDR; written twice
// (`hdr`, into which the flares are blended, and `sky`, kept for the tests).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
layout(location = 1) out vec4 sky;
void main() {
    vec2 px = gl_FragCoord.xy, sun = params.light * frame.resolution.xy;
    vec3 c = mix(vec3(0.3, 0.2, 0.14), vec3(0.03, 0.05, 0.14), clamp(1.0 - uv.y * 1.2, 0.0, 1.0));
    float d = length(px - sun) / frame.resolution.y;
    c += params.sun_radiance * (d < 0.02 ? vec3(1.0, 0.95, 0.85) : vec3(0.0)) + vec3(1.0, 0.7, 0.4) * 0.006 / (d * d + 0.002);
    float hill = 0.78 + 0.05 * sin(uv.x * 9.0) + 0.03 * sin(uv.x * 23.0 + 1.0);
    if (uv.y > hill) c = vec3(0.02, 0.025, 0.03);
    hdr = sky = vec4(c, 1.0);
}
