#version 450
// "Dark polygon ... blend polygon into frame buffer" (L4457-4460): a disc of uniform darkness
// params.opacity: colour and visibility are multiplied by (1 - opacity) (blend src zero, dst
// one_minus_src_alpha; vis only in r). Target 2 `blob_id` = blob index + 1 where the disc landed
// (tests: coverage and centroid).
layout(location = 0) in vec2 v_local;
layout(location = 1) flat in int v_blob;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 vis;
layout(location = 2) out vec4 blob_id;
void main() {
    if (dot(v_local, v_local) > 1.0) discard;
    color = vec4(0.0, 0.0, 0.0, params.opacity);
    vis = vec4(0.0, 0.0, 0.0, params.opacity);
    blob_id = vec4(float(v_blob + 1) / 255.0, 0.0, 0.0, 1.0);
}
