#version 450
// Light gl_InstanceIndex's volume: the unit sphere mesh scaled to the light's radius, times 1.1
// so the polygon (inscribed in the unit sphere: its vertices on it, its flat faces inside)
// contains the true sphere. The 16 x 8 mesh's triangles come as close as 0.963 of the radius
// (those next to the equator; 0.980 at the poles), so it needs at least 1 / 0.963 = 1.039:
// volumes-cover-their-lights fails at 1.035 and passes at 1.04; 1.1 leaves room.
#include "deferred/lights.glsl"
layout(location = 0) in vec3 position;
layout(location = 0) flat out int v_light;
// The light itself, evaluated here once per vertex instead of at every covered pixel: the
// fragment shader reads it as constants of the volume (flat). reach.frag reads v_light alone.
layout(location = 1) flat out vec4 v_sphere;  // centre xyz, radius w
layout(location = 2) flat out vec3 v_color;
const float kCover = 1.1;
void main() {
    PointLight l = point_light(gl_InstanceIndex, frame.time);
    v_light = gl_InstanceIndex;
    v_sphere = vec4(l.position, l.radius);
    v_color = l.color;
    gl_Position = frame.view_proj * vec4(l.position + position * l.radius * kCover, 1.0);
    if (gl_InstanceIndex >= params.lights) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
