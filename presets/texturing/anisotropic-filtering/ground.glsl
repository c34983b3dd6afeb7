// The ground plane y = 0, ray-cast per (sub-)pixel so the reference can evaluate the texture
// coordinate anywhere inside a pixel. Texture coordinates: t = (x, -z) * params.density,
// the plane ends at |x| <= params.half_width and -params.extent <= z <= 2.
#ifndef ANISO_GROUND_GLSL
#define ANISO_GROUND_GLSL
// pixel: window coordinates (gl_FragCoord.xy convention, (0,0) top-left corner of the image).
bool ground_uv(vec2 pixel, out vec2 t) {
    vec2 ndc = pixel * frame.resolution.zw * 2.0 - 1.0;
    vec4 w = frame.inv_view_proj * vec4(ndc, 1.0, 1.0);
    vec3 o = frame.camera_pos.xyz, d = normalize(w.xyz / w.w - o);
    float s = -o.y / min(d.y, -1e-6);           // o.y + s d.y = 0 (finite above the horizon too)
    vec3 p = o + s * d;
    t = vec2(p.x, -p.z) * params.density;
    return d.y < 0.0 && abs(p.x) <= params.half_width && p.z <= 2.0 && p.z >= -params.extent;
}
#endif
