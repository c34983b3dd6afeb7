// shadows/shade.frag's visibility for this preset: planar projected shadows do not change the
// shading of the receiver; the flat caster copies darken it afterwards (shadow.frag, blending).
float shadow_visibility(vec3 p, vec3 n, vec3 l) { return 1.0; }
