#version 450
// One column per clear under test. Integer textures are read with texelFetch and compared as
// integers in the shader, because a float readback cannot hold 0xffffffff exactly.
layout(location = 0) out vec4 result;

uniform usampler2D heads;
uniform isampler2D negative;
uniform usampler2D passed;
uniform usampler2D wide;
layout(std430) readonly buffer words { uint words_data[]; };
layout(std430) readonly buffer filled { uint filled_data[]; };

vec4 report(uint got, uint expected) {
    return vec4(got == expected ? 1.0 : 0.0, float(got & 0xffffu), float(got >> 16), 1.0);
}

vec4 report2(uint got_a, uint want_a, uint got_b, uint want_b) {
    return vec4(got_a == want_a && got_b == want_b ? 1.0 : 0.0, float(got_a), float(got_b), 1.0);
}

void main() {
    int x = int(gl_FragCoord.x);
    ivec2 p = ivec2(3, 2);  // any texel: a clear covers the whole image
    uvec4 w = texelFetch(wide, p, 0);
    if (x == 0) result = report(texelFetch(heads, p, 0).r, 0xffffffffu);
    else if (x == 1) result = report(uint(texelFetch(negative, p, 0).r), uint(-7));
    else if (x == 2) result = report(texelFetch(passed, p, 0).r, 7u);
    else if (x == 3) result = report(words_data[15], 0xffffffffu);
    else if (x == 4) result = report(filled_data[15], 0xffffffffu);
    else if (x == 5) result = report2(w.r, 65535u, w.a, 40000u);
    else if (x == 6) result = report2(w.g, 1u, w.b, 2u);
    else result = vec4(0.0);
}
