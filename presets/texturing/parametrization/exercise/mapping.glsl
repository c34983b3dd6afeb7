// EXERCISE — parametrisations (000_c9f7e5de708ecbb3.txt L1528-1589): texture coordinates
// computed from the object-space point. The planar and box projections and the cylinder's
// height are given; you write the angle around the y axis that the cylindrical and the
// spherical mapping share (TODO 1), its derivative for the seam-free lookup (TODO 2) and the
// sphere's polar coordinate (TODO 3).
//     passlab run   texturing/parametrization --exercise presets/texturing/parametrization/exercise
//     passlab grade texturing/parametrization --exercise presets/texturing/parametrization/exercise
//   planar:      (u, v) = (x, y) over the bounding box: "dump one of the coordinates" (L1542)
//   cylindrical: u = the angle around y in [0, 1],  v = (y - y_min) / height    (L1548-1551, L1560)
//   spherical:   u = the same angle,  v = the polar angle from the top pole / pi  (L1550-1551, L1564)
//   ("compute angles between vertex and object center", L1550; the slides give no formula)
//   (v here runs from the top: texture row 0 at y_max / the top pole, for all four)
//   box:         project onto the plane of the normal's dominant axis (L1566-1569)
// All have distortions and singularities (L1579-1582): the poles of the sphere, the caps of
// the cylinder, the box's edges.
//
// Pitfall: the angle jumps from +pi to -pi behind the object, so u jumps from 1 to 0 between
// two pixels of a 2x2 quad; the implicit derivative there is ~1 texture width per pixel and
// the sampler picks the smallest mip: a line of the texture's mean colour along the seam. The
// fix: textureGrad with the derivative of the angle itself (TODO 2), which knows nothing of the
// branch cut. (Box mapping has the same problem at face changes: all three projections are
// differentiated in uniform flow, then one is picked.)
#ifndef PARAMETRIZATION_MAPPING_GLSL
#define PARAMETRIZATION_MAPPING_GLSL
const float kTwoPi = 6.28318530718, kPi = 3.14159265359;

struct Param {
    vec2 uv, dx, dy;     // coordinates and their screen derivatives (seam-free)
    float u_jump;        // |implicit derivative| of the raw angle coordinate: > 0.25 at the seam
};

// p: object-space point relative to the bounding box centre, e: box half-extent, n: normal,
// dpx / dpy: dFdx(p) / dFdy(p) taken in uniform control flow.
Param parametrize(int mapping, vec3 p, vec3 e, vec3 n, vec3 dpx, vec3 dpy) {
    Param r;
    // TODO 1: the angle around the y axis as a texture coordinate (L1548-1551, L1560): the
    // angle phi of (x, z) in the xz plane, measured from +x towards +z, over its full turn
    // (-pi, pi] (GLSL's two-argument atan: mind which argument is which), mapped to [0, 1]:
    //     u = phi / (2 pi) + 1/2        (so -z is u = 0.25, +x is 0.5, +z is 0.75)
    float angle_u = 0.0;
    r.u_jump = max(abs(dFdx(angle_u)), abs(dFdy(angle_u)));
    float rxz2 = max(p.x * p.x + p.z * p.z, 1e-12);
    // TODO 2: the screen derivatives of u for textureGrad (the seam fix, see the pitfall
    // above): phi jumps by 2 pi where atan wraps (behind the object, -x), but its derivative
    // does not. With dpx = dFdx(p), dpy = dFdy(p) (given), the chain rule on phi(x, z):
    //     d phi = (x dz - z dx) / (x^2 + z^2),     du = d phi / (2 pi)
    // for du.x (along the screen's x) and du.y (along its y). rxz2 = x^2 + z^2, kept off 0.
    vec2 du = vec2(0.0);
    // Box: three planar projections, each mapped to [0, 1]^2 over the box's faces.
    vec2 px = vec2(-p.z, p.y) / (2.0 * e.zy) + 0.5, py = vec2(p.x, -p.z) / (2.0 * e.xz) + 0.5,
         pz = vec2(p.x, p.y) / (2.0 * e.xy) + 0.5;
    vec2 px_dx = dFdx(px), px_dy = dFdy(px), py_dx = dFdx(py), py_dy = dFdy(py), pz_dx = dFdx(pz), pz_dy = dFdy(pz);
    // 1 - polar angle / pi: 1 at the top pole, so that after the flip below the texture's
    // top row lands on the top pole like the other mappings' top
    // TODO 3: the sphere's v (L1550-1551, L1564), before the flip below: the polar angle
    // theta between p and the +y axis (0 at the top pole, pi at the bottom one), as
    //     v_sphere = 1 - theta / pi
    // (1 at the top pole, so that after the flip the texture's top row lands there). Keep the
    // cosine you take the arc cosine of inside [-1, 1].
    float v_sphere = 0.0;
    vec2 dv_sphere = vec2(dFdx(v_sphere), dFdy(v_sphere));   // no seam in v
    if (mapping == MAPPING_PLANAR) {
        r.uv = pz; r.dx = pz_dx; r.dy = pz_dy;
        r.u_jump = 0.0;
    } else if (mapping == MAPPING_CYLINDRICAL) {
        r.uv = vec2(angle_u, (p.y + e.y) / (2.0 * e.y));
        r.dx = vec2(du.x, dpx.y / (2.0 * e.y));
        r.dy = vec2(du.y, dpy.y / (2.0 * e.y));
    } else if (mapping == MAPPING_SPHERICAL) {
        r.uv = vec2(angle_u, v_sphere);
        r.dx = vec2(du.x, dv_sphere.x);
        r.dy = vec2(du.y, dv_sphere.y);
    } else {
        vec3 a = abs(n);
        if (a.x >= a.y && a.x >= a.z) { r.uv = px; r.dx = px_dx; r.dy = px_dy; }
        else if (a.y >= a.z) { r.uv = py; r.dx = py_dx; r.dy = py_dy; }
        else { r.uv = pz; r.dx = pz_dx; r.dy = pz_dy; }
        r.u_jump = 0.0;
    }
    r.uv.y = 1.0 - r.uv.y;   // texture row 0 (v = 0) at the top
    r.dx.y = -r.dx.y;
    r.dy.y = -r.dy.y;
    return r;
}
#endif
