#version 450
// Dual depth peeling, one pass (000_c9f7e5de708ecbb3.txt L4189-4199: "Peel front and back in one
// pass", "Compare current depth with min/max values", "Use previous front/back layer depth values
// in current pass"). `prev` holds (1 - near, far) of what is left to peel. A fragment
//   - outside [near, far] was peeled by an earlier pass: nothing;
//   - at near is this pass's front layer, at far its back layer (near == far: front only);
//   - strictly inside is left for later: it writes (1 - z, z) to the next range (MAX blending).
// All three targets blend with MAX and are cleared to 0, so "nothing" is an output of 0. The
// front and back layers hold one fragment per pixel (distinct depths), premultiplied.
// Comparisons are made in the stored encoding (1 - z is recomputed exactly as dual_init.frag
// and this pass wrote it), never by decoding 1 - (1 - z), which need not round back to z.
layout(early_fragment_tests) in;
layout(location = 0) flat in vec4 v_color;
layout(location = 0) out vec4 minmax;
layout(location = 1) out vec4 front;
layout(location = 2) out vec4 back;
uniform sampler2D prev;

void main() {
    vec2 mm = texelFetch(prev, ivec2(gl_FragCoord.xy), 0).rg;
    float z = gl_FragCoord.z, nz = 1.0 - z;
    minmax = vec4(0.0); front = vec4(0.0); back = vec4(0.0);
    vec4 pm = vec4(v_color.rgb * v_color.a, v_color.a);
    // L4194-4195 "If < min write to front layer, if > max write to back layer"
    // (min and max of what is left: the outermost remaining fragments are the two layers).
    if (nz > mm.x || z > mm.y) return;                   // peeled already
    if (nz == mm.x) front = pm;                          // the nearest remaining fragment
    else if (z == mm.y) back = pm;                       // the farthest remaining fragment
    else minmax = vec4(nz, z, 0.0, 0.0);                 // left for the next pass
}
