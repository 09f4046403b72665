#version 330 core
// Fill with a soft top light, an optional pattern (1: hatched, for infinite mass at rest;
// 2: striped, for kinematic platforms) and a crisp outline.
in vec2 vLocalPx;
flat in vec2 vHalfPx;
flat in vec4 vFill;
flat in vec4 vOutline;
flat in vec2 vStyle;

out vec4 fragColor;

void main() {
    float edge = min(vHalfPx.x - abs(vLocalPx.x), vHalfPx.y - abs(vLocalPx.y));
    vec4 color = vFill;
    float shade = 0.92 + 0.08 * (vLocalPx.y / max(vHalfPx.y, 1.0));
    color.rgb *= shade;
    if (vStyle.y > 0.5 && vStyle.y < 1.5) {
        if (mod(vLocalPx.x + vLocalPx.y, 9.0) < 2.5) color.rgb *= 0.72;
    } else if (vStyle.y > 1.5) {
        if (mod(vLocalPx.x - vLocalPx.y, 14.0) < 5.0) color.rgb *= 0.82;
    }
    if (edge < vStyle.x) color = vOutline;
    fragColor = color;
}
