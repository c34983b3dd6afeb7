// Shared by lod.vert and morph.vert, so both compute clip position and varyings by the same
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
