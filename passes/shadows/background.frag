#version 450
// First pass of the shared scene's view: the sky colour, and the background values of the debug
// targets (a pass clear would put one colour into all three): `vis` = (1, 0, 0, 0) (lit,
// nothing), `world` = 0 (object 0 = background).
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 vis;
layout(location = 2) out vec4 world;
void main() {
    color = vec4(0.55, 0.65, 0.8, 1.0);
    vis = vec4(1.0, 0.0, 0.0, 0.0);
    world = vec4(0.0);
}
