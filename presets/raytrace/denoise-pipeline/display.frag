#version 450
// One stage of the pipeline (show), from the half-resolution working images to the view.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D raw;
uniform sampler2D spatial;
uniform sampler2D temporal;
uniform sampler2D bilateral;
uniform sampler2D taa;
uniform sampler2D converged;
void main() {
    vec3 c = params.show == SHOW_RAW ? texture(raw, uv).rgb
           : params.show == SHOW_SPATIAL ? texture(spatial, uv).rgb
           : params.show == SHOW_TEMPORAL ? texture(temporal, uv).rgb
           : params.show == SHOW_BILATERAL ? texture(bilateral, uv).rgb
           : params.show == SHOW_CONVERGED ? texture(converged, uv).rgb
           : texture(taa, uv).rgb;
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
