#version 450
// The ray-traced shadow presets' G-buffer, the raster half of the hybrid (000_c9f7e5de708ecbb3.txt L5753-5763: "main rendering done with
// rasterization, ... raytracing of shadows"): per pixel the world position and shading normal of
// the shared shadow scene's nearest surface (passes/shadows/object.vert), which the shadow-ray
// pass reads as the seed reads vWorldSpacePosition and gNormal (002_644d46bdce7e5305.txt L2162).
// Targets: gpos = (world position, object + 1; 0 = background), gnrm = (unit normal, 1).
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 gpos;
layout(location = 1) out vec4 gnrm;
void main() {
    gpos = vec4(v_world, float(OBJECT + 1));
    gnrm = vec4(normalize(v_normal), 1.0);
}
