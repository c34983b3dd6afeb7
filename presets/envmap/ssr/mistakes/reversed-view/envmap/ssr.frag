#version 450
// envmap/ssr's pass, shared with raytrace/rt-reflections-hybrid (SSR first, rays at its gaps).
// Screen-space reflections (000_c9f7e5de708ecbb3.txt L3968-4130, after Killing Floor 2 as the
// lecture cites it). For every pixel with a non-zero reflection map:
//   1. P from the depth buffer, V = normalize(P - eye), R = reflect(V, N)         (L3999)
//   2. project P and a point P + L R: the screen-space ray (u, v, z_device) and its direction
//      ScreenSpaceReflectionVec = normalize(ss(P + L R) - ss(P))                  (L4000-4003)
//      (z_device is affine along the projected line, so marching it linearly is exact)
//   3. ray march: sample_i = ScreenSpacePos + (i step) ScreenSpaceReflectionVec, i < 16, until
//      sample.z > depth buffer (the ray went behind what the camera sees)         (L4013-4052)
//   4. binary search, 6 halvings between the sample before and the one after    (L4056-4084)
//   5. the reflected colour is the lit image at the intersection's (u, v).
// BUG IN THE PRINTED CODE (L4028-4041, catalogue pitfall): it #defines
// MAX_REFLECTION_RAY_MARCH_STEP 0.02 but the loop multiplies by ReflectionRayMarchStep, which
// is declared nowhere: it does not compile. Fixed here: one name, kept as a param
// (params.march_step, default the printed 0.02).
// ADDED (catalogue pitfall): a thickness test. The printed test `RaySample.z > ZBufferVal`
// accepts any point behind the depth buffer, however far behind: rays passing *behind* an
// object "hit" its front. Here, after the binary search, the ray counts as hitting only when it
// ends at most params.thickness (view-space units) behind the depth buffer; otherwise it marches
// on. thickness = 0 is the printed test.
// Misses (off screen, no intersection within the steps: L4086-4120) leave alpha 0: the
// composite falls back to the environment (L4124, "blend with cubemaps").
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ssr;   // rgb: reflected colour, a: 1 hit, 0 miss
uniform sampler2D lit;
uniform sampler2D gbuf;              // xyz world normal, w reflection map
uniform sampler2D depth;

// Distance in front of the camera for a depth-buffer value (perspective: xy do not matter).
float view_depth(float z) {
    vec4 v = frame.inv_proj * vec4(0.0, 0.0, z, 1.0);
    return -v.z / v.w;
}
// Nearest texel for the march and the thickness test: a filtered depth would blend across
// silhouettes and hide the jumps the thickness test looks for. The binary search reads the
// bilinear depth: on a smooth surface it is the plane through the texel centres, so the search
// converges to a sub-pixel crossing (a pixel of error is 0.025 of colour on the ball, > 4/255).
// (Bilinear by hand from the four texels around st: the sampler's linear filter is not applied
// to this depth format here.) depth_nearest4 is the nearest surface among the same four.
void depth_quad(vec2 st, out vec4 z, out vec2 f) {
    vec2 t = st * frame.resolution.xy - 0.5;
    f = fract(t);
    ivec2 p = ivec2(floor(t)), hi = ivec2(frame.resolution.xy) - 1;
    z = vec4(texelFetch(depth, clamp(p, ivec2(0), hi), 0).r, texelFetch(depth, clamp(p + ivec2(1, 0), ivec2(0), hi), 0).r,
             texelFetch(depth, clamp(p + ivec2(0, 1), ivec2(0), hi), 0).r, texelFetch(depth, clamp(p + ivec2(1, 1), ivec2(0), hi), 0).r);
}
float depth_smooth(vec2 st) {
    vec4 z; vec2 f;
    depth_quad(st, z, f);
    return mix(mix(z.x, z.y, f.x), mix(z.z, z.w, f.x), f.y);
}
float depth_nearest4(vec2 st) {
    vec4 z; vec2 f;
    depth_quad(st, z, f);
    return min(min(z.x, z.y), min(z.z, z.w));
}
float depth_at(vec2 st) { return texelFetch(depth, clamp(ivec2(st * frame.resolution.xy), ivec2(0), ivec2(frame.resolution.xy) - 1), 0).r; }
vec3 to_screen(vec3 p) {
    vec4 c = frame.view_proj * vec4(p, 1.0);
    return vec3(c.xy / c.w * 0.5 + 0.5, c.z / c.w);
}
bool on_screen(vec3 s) { return all(greaterThanEqual(s, vec3(0.0))) && all(lessThanEqual(s, vec3(1.0))); }

// The listing's GetReflection with the binary search folded in.
bool GetReflection(vec3 ScreenSpaceReflectionVec, vec3 ScreenSpacePos, out vec3 ReflectionColor) {
    vec3 PrevRaySample = ScreenSpacePos;
    for (int RayStepIdx = 0; RayStepIdx < params.march_steps; RayStepIdx++) {
        vec3 RaySample = (float(RayStepIdx) * params.march_step) * ScreenSpaceReflectionVec + ScreenSpacePos;
        if (!on_screen(RaySample)) return false;  // "reflections outside viewport" (L4089)
        float ZBufferVal = depth_at(RaySample.xy);
        if (RaySample.z > ZBufferVal) {
            vec3 MinRaySample = PrevRaySample, MaxRaySample = RaySample, MidRaySample = RaySample;
            for (int i = 0; i < params.binary_steps; i++) {
                MidRaySample = mix(MinRaySample, MaxRaySample, 0.5);
                float z = depth_smooth(MidRaySample.xy);
                if (MidRaySample.z > z) MaxRaySample = MidRaySample;
                else MinRaySample = MidRaySample;
            }
            // Thickness, after the search: at a true crossing of a surface the ray ends up just
            // behind it (the gap shrinks with every halving); when it passed behind an object the
            // search converges on the object's silhouette, where the depth buffer jumps, and the
            // gap stays as large as the distance behind it.
            // (Against the nearest of the four texels the search interpolated: at a silhouette
            // the smoothed depth ramps down to the background, and only the nearest texel shows
            // how far behind the object the ray really is.)
            float gap = view_depth(MaxRaySample.z) - view_depth(depth_nearest4(MaxRaySample.xy));
            if (params.thickness <= 0.0 || gap <= params.thickness) {
                ReflectionColor = textureLod(lit, MidRaySample.xy, 0.0).rgb;
                return true;
            }
        }
        PrevRaySample = RaySample;
    }
    return false;
}

void main() {
    ssr = vec4(0.0);
    // The pixel whose ray this is: this one, or with ssr_resolution = half (the ssr image half the
    // view in x and y) the even pixel (2i, 2j) of the full-resolution G-buffer and depth, one ray
    // per 2x2 block; the composite reads it at p / 2. frame.resolution stays the view's.
    vec2 st = params.ssr_resolution == SSR_RESOLUTION_HALF
            ? (vec2(ivec2(gl_FragCoord.xy) * 2) + 0.5) * frame.resolution.zw : uv;
    vec4 g = texture(gbuf, st);
    if (g.w <= 0.0) return;  // "black pixels do not show SSR" (L3992)
    float z = depth_at(st);
    vec4 w = frame.inv_view_proj * vec4(st * 2.0 - 1.0, z, 1.0);
    vec3 P = w.xyz / w.w, N = normalize(g.xyz);
    vec3 V = normalize(frame.camera_pos.xyz - P), R = reflect(V, N);  // MISTAKE: V from the surface to the eye
    // The second point, 10 units along R as in Killing Floor 2, pulled in when R comes back
    // towards the camera so that it stays in front of it (a point behind the eye projects wrongly).
    float L = 10.0;
    vec3 pv = (frame.view * vec4(P, 1.0)).xyz, rv = mat3(frame.view) * R;
    if (rv.z > 0.0) L = min(L, 0.9 * -pv.z / rv.z);
    vec3 ss0 = vec3(st, z), ss1 = to_screen(P + L * R);
    vec3 c;
    if (GetReflection(normalize(ss1 - ss0), ss0, c)) ssr = vec4(c, 1.0);
}
