#version 450
// A soft round sprite whose colour and brightness follow the age: additive blending (ONE, ONE:
// "source and destination are simply added ... good for fire effects", 000_c9f7e5de708ecbb3.txt
// L2139-2144), so overlapping particles brighten and the draw order does not matter.
layout(location = 0) in vec2 corner;
layout(location = 1) in float age01;
layout(location = 0) out vec4 color;
void main() {
    float r2 = dot(corner, corner);
    float disc = max(1.0 - r2, 0.0);                     // 0 at the quad's inscribed circle
    vec3 hot = mix(vec3(1.0, 0.8, 0.35), vec3(0.9, 0.2, 0.04), age01);
    color = vec4(hot * (disc * disc * (1.0 - age01) * params.intensity), 0.0);
}
