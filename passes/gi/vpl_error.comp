#version 450
// Test-only: the squared error of the method's indirect term against the one-bounce reference,
// per pixel (rgb), so that a `mean` or `monotone` check on it is the MSE over the image.
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D indirect, reference;
layout(rgba32f) uniform writeonly image2D sq_error;
void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, imageSize(sq_error)))) return;
    vec3 d = texelFetch(indirect, px, 0).rgb - texelFetch(reference, px, 0).rgb;
    imageStore(sq_error, px, vec4(d * d, 1.0));
}
