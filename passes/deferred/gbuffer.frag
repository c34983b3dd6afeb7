#version 450
// Pass 1 of deferred shading (000_c9f7e5de708ecbb3.txt L2885-2894; 003_cfc3b5b225ddab3d.txt
// L419-478): no lighting, only what lighting will need, one image per attribute (MRT):
//   albedo (rgb) + specular intensity (a)   rgba8
//   world normal (xyz, w = 1 marks geometry) rgba16f
//   world position                           rgba32f (the packed layout rebuilds it from depth)
//   octahedral normal                        rg16f   (the packed layout's normal; not written with
//                                                    NO_OCT, for a preset that reads only the fat layout)
#include "deferred/octahedral.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in vec4 v_material;
layout(location = 0) out vec4 albedo;
layout(location = 1) out vec4 normal;
layout(location = 2) out vec4 position;
#ifndef NO_OCT
layout(location = 3) out vec2 normal_oct;
#endif
void main() {
    vec3 n = normalize(v_normal);
    albedo = v_material;
    normal = vec4(n, 1.0);
    position = vec4(v_world, 1.0);
#ifndef NO_OCT
    normal_oct = oct_encode(n);
#endif
}
