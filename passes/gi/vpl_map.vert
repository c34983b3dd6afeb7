#version 450
#extension GL_ARB_shader_viewport_layer_array : require
// The VPLs' paraboloid shadow maps in one layered draw: the box's 5 walls and the blocks' 12
// faces as instances of one finely tessellated plane (the paraboloid warp bends straight edges
// only at vertices, so a block's two-triangle faces would be badly wrong close to a VPL).
// Instance i is surface i % VPL_SURFACES of VPL slot (base + i / VPL_SURFACES) % slots, sent to
// layer = slot with gl_Layer; gl_ClipDistance cuts what does not lie in front of the VPL's surface.
#include "gi/cornell.glsl"
#include "gi/vpl.glsl"
layout(location = 0) in vec3 position;
out gl_PerVertex { vec4 gl_Position; float gl_ClipDistance[1]; };

void main() {
    int k = gl_InstanceIndex % VPL_SURFACES;
    uint slot = (vpl_args.base + uint(gl_InstanceIndex / VPL_SURFACES)) % vpl_args.slots;
    Vpl v = vpls.vpl[slot];
    vec3 p = (vpl_surface(k) * vec4(position, 1.0)).xyz;
    vec4 m = vpl_paraboloid(p, v.position.xyz, normalize(v.normal.xyz + vec3(0.0, 0.0, 1e-7)));
    gl_Layer = int(slot);
    // Only what lies in front of the VPL's tangent plane: surfaces in that plane (the VPL's own
    // floor or face) warp onto the disc's rim, and their triangles, chords of the rim, would
    // cover the whole disc at a tiny depth. An empty slot draws nothing.
    gl_ClipDistance[0] = v.position.w > 0.0 ? m.w - 0.01 : -1.0;
    gl_Position = vec4(m.x, -m.y, m.z, 1.0);
}
