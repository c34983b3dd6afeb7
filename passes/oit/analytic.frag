#version 450
// Analytic sorted reference for the shared OIT scene: at this pixel's centre, evaluate every
// quad of scene.glsl directly (inside its rectangle? its plane depth in front of the opaque
// depth?), sort the hits by depth (selection sort, all of them: no cap) and composite back to
// front with oit_over. Shares no code with any OIT method's storage, sort or blend, so a wrong
// method (or exercise) cannot make its own reference agree.
// The full-screen stack (params.stack = k, up to 32) is known in closed form: quad q lies at
// depth (q+1)/(k+2), so the farthest is q = k-1 and the nearest q = 0. Only the 9-quad scene is
// searched: llvmpipe took 18 s at 160x96 when the search ran over 32-entry private arrays.
#include "oit/scene.glsl"
#include "oit/composite.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;

void main() {
    vec2 ndc = gl_FragCoord.xy * frame.target.zw * 2.0 - 1.0;
    bool stacked = params.stack > 0;
    bool onBar = !stacked && ndc.x >= kOitOpaqueRect.x && ndc.x < kOitOpaqueRect.z
              && ndc.y >= kOitOpaqueRect.y && ndc.y < kOitOpaqueRect.w;
    float opaqueZ = onBar ? kOitOpaqueDepth : 1.0;
    vec3 c = onBar ? kOitOpaqueRgb : kOitBackground;
    if (stacked) {
        for (int q = params.stack - 1; q >= 0; --q) c = oit_over(c, vec4(oit_quad(q, params.stack).rgb, params.alpha));
        color = vec4(c, 1.0);
        return;
    }
    float z[OIT_QUADS]; vec3 rgb[OIT_QUADS]; int n = 0;
    for (int q = 0; q < OIT_QUADS; ++q) {
        OitQuad k = oit_quad(q, params.stack);
        if (ndc.x < k.rect.x || ndc.x >= k.rect.z || ndc.y < k.rect.y || ndc.y >= k.rect.w) continue;
        float d = oit_depth(k, ndc);
        if (d >= opaqueZ) continue;   // the depth test against the opaque scene
        z[n] = d; rgb[n] = k.rgb; ++n;
    }
    // Farthest first, each one over what is behind it.
    for (int done = 0; done < n; ++done) {
        int far = 0;
        for (int i = 1; i < n; ++i) if (z[i] > z[far]) far = i;
        c = oit_over(c, vec4(rgb[far], params.alpha));
        z[far] = -1.0;
    }
    color = vec4(c, 1.0);
}
