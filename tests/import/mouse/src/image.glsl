void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    // A dot where the mouse is: Shadertoy's iMouse.xy is in bottom-left pixels.
    fragColor = vec4(vec3(length(fragCoord - iMouse.xy) < 1.0 ? 1.0 : 0.0), 1.0);
}
