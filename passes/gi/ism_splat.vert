#version 450
#extension GL_ARB_shader_viewport_layer_array : require
// The imperfect shadow maps: every VPL's paraboloid map splatted from its own points in one
// layered point draw (000 L5240-5253: "parabolic shadow map", "coarse approximation of scene as
// point cloud", "imperfect: smaller points"). Instance s = VPL slot s -> gl_Layer = s; vertex j
// = point s + j * slots of the cloud (interleaved subsets, gi/ism.glsl).
//
// Each point stands for a disc (a surfel) of radius R = splat * r in its surface's plane,
// r = sqrt(A / (pi n)) (A the scene's area, n points per VPL: the discs of one subset cover A
// once at splat = 1). The sprite must contain the disc's image: at distance d the disc spans at
// most the angle 2R/d, and the paraboloid s = tan(theta/2) stretches angles by
// ds/dtheta = (1 + s^2)/2; [-1,1] spans `size` texels, so the sprite's side is
//     size_px = (2R/d) * (1 + s^2)/2 * size/2 = R/d * (1 + s^2) * size/2   (+ 1 texel),
// and ism_splat.frag keeps only the sprite's texels whose ray hits the disc, at that hit's depth
// (a square of the centre's depth instead: 62% of the texels right at 8192 points, the sprites of
// points near the VPL covering the map).
#include "gi/ism.glsl"
out gl_PerVertex { vec4 gl_Position; float gl_PointSize; };
layout(location = 0) flat out vec4 v_centre;  // the point in the VPL's frame (xyz), R (w)
layout(location = 1) flat out vec3 v_normal;  // its surface's normal in the VPL's frame

void main() {
    uint slot = uint(gl_InstanceIndex);
    uint i = slot + uint(gl_VertexIndex) * vpl_args.slots;
    Vpl v = vpls.vpl[slot];
    IsmPoint q = ism_points.p[i];
    vec3 n = normalize(v.normal.xyz + vec3(0.0, 0.0, 1e-7));
    vec4 m = vpl_paraboloid(q.position.xyz, v.position.xyz, n);
    mat3 to_local = transpose(vpl_frame(n));
    float radius = params.splat * ism_point_radius(float(params.points));
    float size = float(params.map_size);
    float d = max(m.z * VPL_FAR, 1e-3);
    gl_Layer = int(slot);
    gl_PointSize = clamp(radius / d * (1.0 + dot(m.xy, m.xy)) * 0.5 * size + 1.0, 1.0, 2.0 * size);
    v_centre = vec4(to_local * (q.position.xyz - v.position.xyz), radius);
    v_normal = to_local * q.normal.xyz;
    // As gi/vpl_map.vert: only points strictly in front of the VPL's tangent plane (its own wall
    // warps onto the rim), none for an empty slot: such a point is sent outside the clip volume.
    bool keep = v.position.w > 0.0 && m.w > 0.01;
    gl_Position = keep ? vec4(m.x, -m.y, m.z, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
}
