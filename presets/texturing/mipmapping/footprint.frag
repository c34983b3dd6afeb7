#version 450
// r: the level the sampler would pick where one pixel covers 4x4 texels (64 texels over this
// 16-pixel image). g: the memory of the whole chain relative to the base level.
layout(location = 0) out vec2 result;
uniform sampler2D checker;
void main() {
    vec2 uv = gl_FragCoord.xy / 16.0;
    float lod = textureQueryLod(checker, uv).y;
    float base = float(textureSize(checker, 0).x * textureSize(checker, 0).y), total = 0.0;
    for (int l = 0; l < textureQueryLevels(checker); ++l) {
        ivec2 s = max(textureSize(checker, 0) >> l, ivec2(1));  // see means.frag
        total += float(s.x * s.y);
    }
    result = vec2(lod, total / base);
}
