// Shared by the plain and the geomorphing vertex shaders (tests/graphs/simplify lod.vert and
// morph.vert, presets/visibility/lod-geomorph), so both compute clip position and varyings by the same
// instructions: a morph at factor 0 or 1 then rasterises exactly like the mesh it equals.
layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec2 v_uv;
layout(location = 2) out float v_depth;

void emit(vec3 position, vec3 normal, vec2 uv) {
    v_normal = normal;
    v_uv = uv;
    v_depth = -(frame.view * vec4(position, 1.0)).z;  // view-space distance along the axis
    gl_Position = frame.view_proj * vec4(position, 1.0);
}

// Geomorph (Hoppe 1996; 000_c9f7e5de708ecbb3.txt L5915-5925): a vertex of the fine LOD slides
// towards the coarse vertex it collapses into, a (1 - f) + b f. Not mix(): its a + (b - a) f is
// not exactly b at f = 1, and the ends must equal the two LODs bit for bit.
vec3 pl_geomorph(vec3 a, vec3 b, float f) { return a * (1.0 - f) + b * f; }
vec2 pl_geomorph(vec2 a, vec2 b, float f) { return a * (1.0 - f) + b * f; }
