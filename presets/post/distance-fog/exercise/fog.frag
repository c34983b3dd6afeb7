#version 450
// EXERCISE — distance fog as a post-process (000_c9f7e5de708ecbb3.txt L2953-3017).
// The scene is drawn; this pass reads its colour and its depth buffer and blends every pixel
// with the fog colour. Fill in the three TODO blocks, then check your work against the reference:
//     passlab run   post/distance-fog --exercise presets/post/distance-fog/exercise   (live)
//     passlab grade post/distance-fog --exercise presets/post/distance-fog/exercise   (the cases)
// `--set show=factor` shows f instead of the result.
// You have: frame.inv_proj (NDC -> view space), uv (0..1 over the screen), params.mode
// (MODE_LINEAR, MODE_EXP, MODE_EXP2), params.density (d_f), params.start, params.end,
// params.fog_color (c_f).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 fogged;
layout(location = 1) out float factor;
uniform sampler2D color;
uniform sampler2D depth;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float z = texelFetch(depth, p, 0).r;   // the depth buffer's value: NDC z, not a distance

    // TODO 1: d, the fragment's distance from the camera (L2989, and the listing L3012-3013:
    // length(camera.position - p)). A post-process has no p: rebuild the pixel's view-space
    // position from its NDC point (x, y from uv, z from the depth buffer) through the inverse
    // projection (mind the homogeneous w). In view space the camera sits at the origin.
    float d = 0.0;

    // TODO 2: the fog factor f (1 = no fog, 0 = only fog), L2985-2987, for params.mode:
    //     linear  f = (d_end - d) / (d_end - d_start)   kept in [0, 1] (the slide does not say so,
    //                                                    but past d_end it goes negative)
    //     exp     f = e^(-d_f d)
    //     exp2    f = e^(-(d_f d)^2)
    float f = 1.0;

    vec3 cs = texelFetch(color, p, 0).rgb;   // c_s, the surface colour
    // TODO 3: blend surface and fog colour by f (L2971: c = f c_s + (1 - f) c_f).
    fogged = vec4(cs, 1.0);
    factor = f;
}
