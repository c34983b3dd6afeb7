#version 450
// "Every value occurs in the source", made checkable: member.r = 1 where the texel of `subject`
// equals (exactly, in RGB) some texel of `source`, else 0. Both are 8-bit images, so equality is
// exact; a blend of two source values, a filtered lookup or a colour shift shows up as 0.
// Only source texels with alpha > 0 count, so a source can leave out a region (a hole: what
// image-completion may copy from is the picture outside it). The check is then `range`
// min = max = 1 on member (over a mask for a region).
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D subject;
uniform sampler2D source;
layout(rgba8) uniform writeonly image2D member;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(member)))) return;
    vec3 c = texelFetch(subject, p, 0).rgb;
    ivec2 size = textureSize(source, 0);
    bool found = false;
    for (int y = 0; y < size.y && !found; ++y)
        for (int x = 0; x < size.x && !found; ++x)
        {
            vec4 s = texelFetch(source, ivec2(x, y), 0);
            found = s.a > 0.0 && s.rgb == c;
        }
    imageStore(member, p, vec4(found ? 1.0 : 0.0, 0.0, 0.0, 1.0));
}
