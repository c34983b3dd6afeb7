// The one lighting equation both modes use: Lambert + Blinn-Phong, evaluated per vertex or per
// pixel depending on the mode.
vec3 blinn_phong(vec3 n, vec3 p) {
    vec3 l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - p), h = normalize(l + v);
    float d = max(dot(n, l), 0.0);
    return vec3(0.6, 0.35, 0.25) * d + vec3(d > 0.0 ? pow(max(dot(n, h), 0.0), params.shininess) : 0.0);
}
