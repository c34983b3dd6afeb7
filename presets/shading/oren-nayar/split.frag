#version 450
// Left of `split` (a fraction of the width) the Lambert image, right of it Oren-Nayar, with a
// thin dark line between; linear radiance clamped into the sRGB target.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D lambert_hdr;
uniform sampler2D oren_nayar_hdr;
void main() {
    vec3 c = uv.x < params.split ? texture(lambert_hdr, uv).rgb : texture(oren_nayar_hdr, uv).rgb;
    if (abs(uv.x - params.split) * frame.resolution.x < 0.75) c = vec3(0.0);
    color = vec4(clamp(c, 0.0, 1.0), 1.0);
}
