#version 450
// The carrier surface with its parameterisation derivatives P_u = dP/du, P_v = dP/dv
// (001_fe43b953f362fae7.txt L578-595: "easy: differentiate, treat other vars as constant"),
// analytic for passlab's generators (host/scene/generators.cpp), like 001's cylinder
// example (L622-642):
//   plane  P = ((u - 0.5) s, 0, (v - 0.5) s):        P_u = (s, 0, 0),  P_v = (0, 0, s)
//   sphere P = r (sin(pi v) sin(2 pi u), cos(pi v), sin(pi v) cos(2 pi u)):
//          P_u = 2 pi r sin(theta) (cos phi, 0, -sin phi)
//          P_v = pi r (cos(theta) sin phi, -sin theta, cos(theta) cos phi)
// Both are left-handed (P_u x P_v points inwards), which blinn_bump_normal handles.
// SURFACE 0: plane of size PLANE_SIZE; 1: sphere (radius from the position). VISIBLE hides it.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec2 v_uv;
layout(location = 2) out vec3 v_n;
layout(location = 3) out vec3 v_pu;
layout(location = 4) out vec3 v_pv;
const float kPi = 3.14159265358979;
void main() {
    v_world = position;
    v_uv = uv;
    v_n = normal;
#if SURFACE == 0
    v_pu = vec3(PLANE_SIZE, 0.0, 0.0);
    v_pv = vec3(0.0, 0.0, PLANE_SIZE);
#else
    float r = length(position), phi = 2.0 * kPi * uv.x, theta = kPi * uv.y;
    v_pu = 2.0 * kPi * r * sin(theta) * vec3(cos(phi), 0.0, -sin(phi));
    v_pv = kPi * r * vec3(cos(theta) * sin(phi), -sin(theta), cos(theta) * cos(phi));
#endif
    gl_Position = frame.view_proj * vec4(position, 1.0);
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
