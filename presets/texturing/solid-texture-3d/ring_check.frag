#version 450
// T at chosen points (turbulence must be 0 for the exact values):
//   x = 0..3: x^2 + y^2 = 1.5 at angles 0, 1, 2, 3 rad and z = -7, -1, 0.5, 9   -> dark brown
//   x = 4: x^2 + y^2 = 1 exactly (point (1, 0)) -> dark brown (1 <= r^2 < 2, the band's start)
//   x = 5: 0.999 -> light brown;  x = 6: 2 exactly -> yellow;  x = 7: 3 exactly -> light brown
#include "solid.glsl"
layout(location = 0) out vec4 color;
void main() {
    int i = int(gl_FragCoord.x);
    const float kZ[4] = float[](-7.0, -1.0, 0.5, 9.0);
    vec3 p;
    if (i < 4) p = vec3(sqrt(1.5) * cos(float(i)), sqrt(1.5) * sin(float(i)), kZ[i]);
    else if (i == 4) p = vec3(1.0, 0.0, 3.0);
    else if (i == 5) p = vec3(sqrt(0.999), 0.0, 0.0);
    else if (i == 6) p = vec3(1.0, 1.0, -2.0);
    else p = vec3(1.0, sqrt(2.0), 0.0);
    color = vec4(carved_wood(p), 1.0);
}
