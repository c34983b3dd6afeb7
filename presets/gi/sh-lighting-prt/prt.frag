#version 450
// Writes the interpolated vertex radiance (linear) and marks the pixel as geometry (the mask of
// the furnace-like checks).
layout(location = 0) in vec3 v_radiance;
layout(location = 0) out vec4 hdr;
layout(location = 1) out vec4 coverage;
void main() {
    hdr = vec4(v_radiance, 1.0);
    coverage = vec4(1.0);
}
