// Blob shadows ("approximate shadows", 000_c9f7e5de708ecbb3.txt L4445-4481): a dark disc per
// caster, "cast ray from light source through object center, blend polygon into frame buffer at
// location of hit" (L4458-4460). The receiver is the shared ground, n.p + d = 0 with (n, d) =
// (0, 1, 0, 0). With the light homogeneous, L = (l, w), the ray from the light through the
// centre c runs along e = w c - l (c - l for a point light, -l for the sun) and meets the plane at
//     H = c + s e,   s = -(n.c + d) / (n.e)
// Each blob is a disc of radius BLOB_RADIUS[i] * params.blob_scale around H, in the plane.
#ifndef PASSLAB_BLOB_GLSL
#define PASSLAB_BLOB_GLSL
#include "shadows/scene.glsl"
#include "shadows/light_homogeneous.glsl"

const vec4 kReceiver = vec4(0.0, 1.0, 0.0, 0.0);
const int kBlobs = 2;                                   // the box (object 1) and the ball (object 2)
const float BLOB_RADIUS[kBlobs] = float[](0.6, 0.5);    // about each caster's half-width

vec3 blob_centre(int i) { return shadow_model(i + 1)[3].xyz; }   // the model's translation

vec3 blob_hit(int i) {
    vec3 c = blob_centre(i);
    vec4 L = shadow_light_homogeneous();
    vec3 e = L.w * c - L.xyz;
    float s = -(dot(kReceiver.xyz, c) + kReceiver.w) / dot(kReceiver.xyz, e);
    return c + s * e;
}

float blob_radius(int i) { return BLOB_RADIUS[i] * params.blob_scale; }
#endif
