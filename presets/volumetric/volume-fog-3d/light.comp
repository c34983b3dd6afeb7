#version 450
// Baked (bake = true: again only when a param changes): the sun's transmittance at every voxel
// centre of the density texture, exp(-sum rho dt) over 16 midpoint samples from the voxel to the
// box's far side along the light. The view march then reads it instead of marching to the light
// at every step (32^3 x 16 samples once, instead of W x H x steps x 8 every frame).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(r32f) uniform writeonly image3D light;
uniform sampler3D density;
#include "fog_density.glsl"
void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    ivec3 n = imageSize(light);
    if (any(greaterThanEqual(v, n))) return;
    vec3 p = (vec3(v) + 0.5) / vec3(n) * 2.0 - 1.0;
    vec3 l = normalize(params.light_dir);
    float ts = box_hit(p, l).y, dts = ts / 16.0, tau = 0.0;
    for (int j = 0; j < 16; j++) tau += rho(p + l * ((float(j) + 0.5) * dts)) * dts;
    imageStore(light, v, vec4(exp(-tau)));
}
