#version 450
// The bake (runs once, `bake = true`, and again when a param changes): one thread per lightmap
// texel of the ground, whose uv is the plane generator's (u along +x, v along +z, size 6):
// p = ((u - 0.5) 6, 0, (v - 0.5) 6) at the texel centre, the area light's visibility from p.
// SIZE_SCALE multiplies the light's radius (the test-only second bake at twice the size).
layout(local_size_x = 8, local_size_y = 8) in;
#include "area_light.glsl"
layout(rgba16f) uniform writeonly image2D baked;
void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy), size = imageSize(baked);
    if (any(greaterThanEqual(t, size))) return;
    vec2 uv = (vec2(t) + 0.5) / vec2(size);
    vec3 p = vec3((uv.x - 0.5) * 6.0, 0.0, (uv.y - 0.5) * 6.0);
    float v = area_light_visibility(p, params.light_size * SIZE_SCALE);
    imageStore(baked, t, vec4(v, v, v, 1.0));
}
