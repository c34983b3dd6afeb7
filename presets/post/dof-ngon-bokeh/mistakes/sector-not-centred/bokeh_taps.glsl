// EXERCISE — TODO 1, 2 here and TODO 3 in dof.frag. Check your work against the reference:
//     passlab run   post/dof-ngon-bokeh --exercise presets/post/dof-ngon-bokeh/exercise
//     passlab grade post/dof-ngon-bokeh --exercise presets/post/dof-ngon-bokeh/exercise
// getBokehTapSampleCoord of 002_644d46bdce7e5305.txt L1474-1487 (again at L1510-1522): a tap
// of a (si + 1)^2 grid over the unit square to the unit disc by Shirley's concentric map, then
// the disc to an n-gon (002 L1437-1455):
//   (a, b) = 2 o - 1;  region |a| > |b|:  r = a, theta = pi/4 (b / a);  else r = b,
//   theta = pi/2 - pi/4 (a / b)          (r may be negative: the point lands at theta + pi)
//   theta += f phi_shutter_max
//   r_ngon = r (cos(pi/n) / cos(theta - (2 pi/n) floor((n theta + pi) / (2 pi))))^f
// f = 0: the disc; f = 1: the n-gon of circumradius 1 whose edge normals point at 2 pi k / n.
// PITFALL (fixed and stated): with r < 0 the point lies at theta + pi, but the printed code
// takes the n-gon's radius at theta. Even n-gons are symmetric under a half turn, so nothing
// shows; for odd n (5, 7) half the taps follow the mirrored polygon and stick out of the
// pentagon by up to 0.19 of its radius. NGON_ANGLE_FIXED = 1 evaluates the n-gon at the
// direction the tap really has; 0 keeps the printed code.
// Note: the shutter rotation turns the sample pattern inside the polygon, not the polygon.
#ifndef PASSLAB_BOKEH_TAPS_GLSL
#define PASSLAB_BOKEH_TAPS_GLSL
const float PI = 3.14159265359;

// o = tap sample xy, f = f-factor, n = diaphragm shape ngon, phiShutterMax = max. lens shutter rotation
vec2 getBokehTapSampleCoord(const in vec2 o, const in float f, const float n, const in float phiShutterMax, bool fixed_angle) {
    vec2 ab = (o * 2.0) - vec2(1.0);
    // TODO 1: Shirley's concentric map (L1474-1487) of the square point ab in [-1, 1]^2 to the
    // disc, as phir = (theta, r): in the region |a| > |b|, r = a and theta = pi/4 (b / a); else
    // r = b and theta = pi/2 - pi/4 (a / b). Guard the divisions at the centre (theta 0 when
    // the divisor is ~0). r may be negative: the point then lies at theta + pi.
    vec2 phir = ((ab.x * ab.x) > (ab.y * ab.y)) ? vec2((abs(ab.x) > 1e-8) ? ((PI * 0.25) * (ab.y / ab.x)) : 0.0, ab.x)
                                                : vec2((abs(ab.y) > 1e-8) ? ((PI * 0.5) - ((PI * 0.25) * (ab.x / ab.y))) : 0.0, ab.y);
    phir.x += f * phiShutterMax;
    // TODO 2: morph the disc to the n-gon of circumradius 1 (L1437-1455): scale r by
    //     (cos(pi/n) / cos(t - (2 pi/n) floor((n t + pi) / (2 pi))))^f      (only when f > 0)
    // where t is the tap's direction: theta, plus pi when fixed_angle is set and r < 0 (the
    // printed code, fixed_angle false, uses theta alone). The floor picks the polygon sector
    // whose edge normal is nearest to t; cos(pi/n) is the apothem.
    float t = phir.x + ((fixed_angle && phir.y < 0.0) ? PI : 0.0);  // the tap's real direction
    phir.y *= (f > 0.0) ? pow((cos(PI / n) / cos(t - ((2.0 * (PI / n)) * floor((n * t) / (2.0 * PI))))), f) : 1.0;
    return vec2(cos(phir.x), sin(phir.x)) * phir.y;
}

// The grid coordinate of tap (sx, sy) of an (si + 1)^2 grid: printed sx / si (0 and 1
// included: the outer ring of 4 si taps all lands on |p| = 1), or centred (sx + 0.5) / (si + 1)
// (uniform over the disc: mean |p|^2 -> 1/2).
vec2 bokeh_grid(vec2 s, vec2 si, bool centred) { return centred ? (s + 0.5) / (si + 1.0) : s / si; }
#endif
