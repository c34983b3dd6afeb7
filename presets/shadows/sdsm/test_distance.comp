#version 450
// Test-only: the view distance -z_view of each pixel's world point (the `world` target of the
// shading passes), to check the reduction's input `zview` against.
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D world;
layout(r32f) uniform writeonly image2D zcheck;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(zcheck)))) return;
    vec4 w = texelFetch(world, p, 0);
    imageStore(zcheck, p, vec4(w.w > 0.0 ? -(frame.view * vec4(w.xyz, 1.0)).z : 0.0));
}
