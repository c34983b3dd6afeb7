#version 450
// Light gl_InstanceIndex's volume: the unit sphere mesh scaled to the light's radius, times 1.1
// so the polygon (inscribed in the unit sphere) contains the true sphere: a 16-segment ring's
// edges lie at cos(pi/16) = 0.981, the 8-ring poles at cos(pi/8) = 0.924 of the radius.
#include "deferred/lights.glsl"
layout(location = 0) in vec3 position;
layout(location = 0) flat out int v_light;
const float kCover = 1.1;
void main() {
    PointLight l = point_light(gl_InstanceIndex, frame.time);
    v_light = gl_InstanceIndex;
    gl_Position = frame.view_proj * vec4(l.position + position * l.radius * kCover, 1.0);
    if (gl_InstanceIndex >= params.lights) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
