#version 450
// Known points of each mapping (mapping.glsl; the cube's half-extent e = 0.5, the sphere's
// radius 0.6). r = |uv - expected| (max of the two), g, b = uv.
//   x = 0  planar: (u, v) does not depend on z: |uv(p) - uv(p + 0.4 z)|         expected 0
//   x = 1  planar, the box's top-left front corner (-e, e, *)                   (0, 0)
//   x = 2  cylindrical, top edge on the +z axis: angle pi/2                      (0.75, 0)
//   x = 3  spherical, the top pole: v = 0; u is undefined there (atan(0, 0): the singularity
//          of L1581, lavapipe returns 0.875), so only v is checked          (*, 0)
//   x = 4  spherical, the equator on the -z axis: angle -pi/2                    (0.25, 0.5)
//   x = 5  box, +x face centre                                                   (0.5, 0.5)
//   x = 6  box, +x face, top corner at -z: seen from +x, -z is to the right      (1, 0)
//   x = 7  box, +z face, bottom corner at +x                                     (1, 1)
#include "mapping.glsl"
layout(location = 0) out vec4 result;
void main() {
    int i = int(gl_FragCoord.x);
    const float e = 0.5, r = 0.6;
    vec3 ev = vec3(e), z0 = vec3(0.0);
    vec2 uv, expect = vec2(0.0);
    if (i == 0) {
        vec3 p = vec3(0.3, 0.2, 0.1);
        uv = abs(parametrize(MAPPING_PLANAR, p, ev, vec3(0, 0, 1), z0, z0).uv -
                 parametrize(MAPPING_PLANAR, p + vec3(0.0, 0.0, 0.4), ev, vec3(0, 0, 1), z0, z0).uv);
    } else if (i == 1) { uv = parametrize(MAPPING_PLANAR, vec3(-e, e, 0.2), ev, vec3(0, 0, 1), z0, z0).uv; }
    else if (i == 2) { uv = parametrize(MAPPING_CYLINDRICAL, vec3(0.0, e, e), ev, vec3(0, 0, 1), z0, z0).uv; expect = vec2(0.75, 0.0); }
    else if (i == 3) { uv = parametrize(MAPPING_SPHERICAL, vec3(0.0, r, 0.0), vec3(r), vec3(0, 1, 0), z0, z0).uv; expect = vec2(uv.x, 0.0); }
    else if (i == 4) { uv = parametrize(MAPPING_SPHERICAL, vec3(0.0, 0.0, -r), vec3(r), vec3(0, 0, -1), z0, z0).uv; expect = vec2(0.25, 0.5); }
    else if (i == 5) { uv = parametrize(MAPPING_BOX, vec3(e, 0.0, 0.0), ev, vec3(1, 0, 0), z0, z0).uv; expect = vec2(0.5); }
    else if (i == 6) { uv = parametrize(MAPPING_BOX, vec3(e, e, -e), ev, vec3(1, 0, 0), z0, z0).uv; expect = vec2(1.0, 0.0); }
    else { uv = parametrize(MAPPING_BOX, vec3(e, -e, e), ev, vec3(0, 0, 1), z0, z0).uv; expect = vec2(1.0, 1.0); }
    vec2 d = abs(uv - expect);
    result = vec4(max(d.x, d.y), uv, 1.0);
}
