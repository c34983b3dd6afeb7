#version 450
// Test only (verify): does every light's volume cover every G-buffer sample its light reaches?
// (003_cfc3b5b225ddab3d.txt L886-887: "rasterize geometry of light volume (only generate
// fragments for covered G-buffer samples)": the rasteriser decides which samples a light
// touches, so a sample the volume misses loses that light, however little it adds there.)
// Two passes write `uncovered`: the fullscreen `reach` (this file) stores minus the number of
// lights whose sphere contains the pixel's sample (distance < radius: falloff > 0); then
// `reach_volumes` (VOLUME) draws the volumes exactly as `volumes` does (volume.vert, back
// faces, depth test greater_equal, additive) and adds 1 for each such light. Every pixel ends
// at 0 when the volumes cover their lights; a sample inside a light's sphere but outside its
// drawn volume stays negative, a volume of a light past params.lights makes it positive.
// Geometric, so it sees a boundary the matching tolerance (2/255) cannot: the falloff
// (1 - (d/r)^2)^2 is below 2/255 for d > 0.955 r.
#include "deferred/lights.glsl"
#ifdef VOLUME
layout(location = 0) flat in int v_light;
#else
layout(location = 0) in vec2 uv;
#endif
layout(location = 0) out float uncovered;
uniform sampler2D normal;
uniform sampler2D position;
bool reaches(int i, vec3 p) {
    PointLight l = point_light(i, frame.time);
    return distance(p, l.position) < l.radius;
}
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    bool geometry = texelFetch(normal, px, 0).w != 0.0;
    vec3 p = texelFetch(position, px, 0).xyz;
#ifdef VOLUME
    if (!geometry) discard;
    uncovered = reaches(v_light, p) ? 1.0 : 0.0;
#else
    float n = 0.0;
    for (int i = 0; geometry && i < params.lights; ++i) n += reaches(i, p) ? 1.0 : 0.0;
    uncovered = -n;
#endif
}
