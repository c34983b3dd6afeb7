#version 450
// Ink where any enabled detector exceeds its limit; paper elsewhere, shaded in two flat tones
// on the rendered objects (analytic scenes stay plain paper so the tests read exact colours).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 final;
uniform sampler2D edges;
uniform sampler2D normal;

const vec3 kLight = vec3(0.4, 0.8, 0.45);  // view space, towards the light

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 e = texelFetch(edges, p, 0);
    bool line = (params.use_depth && (e.r > params.sobel_limit || abs(e.g) > params.laplace_limit)) ||
                (params.use_normals && e.b > params.normal_limit);
    vec4 n = texelFetch(normal, p, 0);
    float tone = 1.0;
    if (params.scene == SCENE_OBJECTS && n.w > 0.0) tone = dot(n.xyz, normalize(kLight)) > 0.25 ? 1.0 : 0.78;
    final = vec4(line ? params.ink : params.paper * tone, 1.0);
}
