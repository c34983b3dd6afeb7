#version 450
// Domain / tessellation evaluation shader: one invocation per generated vertex, at barycentric
// gl_TessCoord in the patch. The point on the flat base triangle is moved along the base
// normal (+y, the plane) by the displacement map (000 L266-303: "displacement map" -> "optimally
// tessellated mesh"):  p = p_base + n * scale * h(uv),  uv = xz / kSize + 0.5.
// The displaced normal from central differences of h:  n = normalize(-dh/dx, 1, -dh/dz).
// equal_spacing: integer levels, L segments per edge; ccw keeps the mesh's winding.
layout(triangles, equal_spacing, ccw) in;
layout(location = 0) in vec3 c_pos[];
layout(location = 0) out vec3 e_world;
layout(location = 1) out vec3 e_normal;
uniform sampler2D height_map;
const float kSize = 2.0;        // the plane's side (mesh size)
const float kEps = 1.0 / 256.0; // difference step in world units: half a height-map texel (256 texels span kSize = 2), so the central difference spans one texel
float height(vec2 xz) { return textureLod(height_map, xz / kSize + 0.5, 0.0).r; }
void main() {
    vec3 b = gl_TessCoord;
    vec3 p = b.x * c_pos[0] + b.y * c_pos[1] + b.z * c_pos[2];
    float s = params.scale;
    p.y += s * height(p.xz);
    float dx = (height(p.xz + vec2(kEps, 0.0)) - height(p.xz - vec2(kEps, 0.0))) / (2.0 * kEps);
    float dz = (height(p.xz + vec2(0.0, kEps)) - height(p.xz - vec2(0.0, kEps))) / (2.0 * kEps);
    e_world = p;
    e_normal = normalize(vec3(-s * dx, 1.0, -s * dz));
    gl_Position = frame.view_proj * vec4(p, 1.0);
}
