#version 450
// Left: the interpolated triangle. Right: the shared-edge quad (0.5 everywhere it is drawn).
// Each panel is a square image shown 1:1 (the view is twice as wide as it is high).
layout(location = 0) out vec4 color;
uniform sampler2D rgb;
uniform sampler2D edge;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    int w = textureSize(rgb, 0).x;
    color = px.x < w ? vec4(texelFetch(rgb, px, 0).rgb, 1.0)
                     : vec4(texelFetch(edge, px - ivec2(w, 0), 0).rrr, 1.0);
}
