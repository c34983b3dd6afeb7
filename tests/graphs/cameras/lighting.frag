#version 450
// A shadow lookup as a lighting pass does it: a floor point projected into the sun's depth map.
layout(location = 0) out vec4 color;
uniform sampler2D sun_depth;
void main() {
    const vec3 points[4] = vec3[](vec3(2, 0, -1), vec3(-2, 0, -1), vec3(2, 0, 1), vec3(-2, 0, 1));
    vec4 clip = cameras.sun.view_proj * vec4(points[int(gl_FragCoord.x)], 1.0);
    vec3 ndc = clip.xyz / clip.w;
    float stored = texture(sun_depth, ndc.xy * 0.5 + 0.5).r;
    color = vec4(ndc.z <= stored ? 1.0 : 0.0, stored, ndc.z, 1.0);
}
