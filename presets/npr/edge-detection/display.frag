#version 450
// The result or one detector (scaled to be visible).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D final;
uniform sampler2D edges;
uniform sampler2D normal;
uniform sampler2D inv_depth;
void main() {
    vec4 e = texture(edges, uv);
    vec3 c = params.show == SHOW_SOBEL     ? vec3(e.r)
             : params.show == SHOW_LAPLACE ? vec3(abs(e.g) * 4.0)
             : params.show == SHOW_NORMALS ? texture(normal, uv).xyz * 0.5 + 0.5
             : params.show == SHOW_DEPTH   ? vec3(texture(inv_depth, uv).r * 2.0)
                                           : texture(final, uv).rgb;
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
