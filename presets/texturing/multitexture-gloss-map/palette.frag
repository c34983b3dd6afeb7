#version 450
// The second texture of the dependent lookup: 4 materials, r = r_s, g = exponent p.
// Material 0 is the grout's (matte); the tiles get 1..3 at random, and 0 for a quarter.
layout(location = 0) out vec4 palette;
const vec2 kMaterials[4] = vec2[](vec2(0.05, 4.0),    // matte
                                  vec2(0.35, 12.0),   // satin
                                  vec2(1.0, 60.0),    // glazed
                                  vec2(0.7, 250.0));  // polished
void main() { palette = vec4(kMaterials[int(gl_FragCoord.x)], 0.0, 1.0); }
