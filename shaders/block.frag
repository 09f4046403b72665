#version 330 core
// Fill with a soft top light and a crisp outline. Variants, chosen by a #define the renderer puts
// after the #version line (one program each, so no pixel pays for a branch it does not take):
//   PATTERNED     the pattern of vStyle.y (1: hatched, for infinite mass at rest; 2: striped,
//                 for kinematic platforms)
//   OUTLINE_ONLY  the outline and nothing inside (the other methods' ghosts)
in vec2 vLocalPx;
flat in vec2 vHalfPx;
flat in vec4 vFill;
flat in vec4 vOutline;
flat in vec2 vStyle;

out vec4 fragColor;

void main() {
    float edge = min(vHalfPx.x - abs(vLocalPx.x), vHalfPx.y - abs(vLocalPx.y));
#ifdef OUTLINE_ONLY
    if (edge >= vStyle.x) discard;
    fragColor = vOutline;
#else
    vec4 color = vFill;
    float shade = 0.92 + 0.08 * (vLocalPx.y / max(vHalfPx.y, 1.0));
    color.rgb *= shade;
#ifdef PATTERNED
    if (vStyle.y > 0.5 && vStyle.y < 1.5) {
        if (mod(vLocalPx.x + vLocalPx.y, 9.0) < 2.5) color.rgb *= 0.72;
    } else if (vStyle.y > 1.5) {
        if (mod(vLocalPx.x - vLocalPx.y, 14.0) < 5.0) color.rgb *= 0.82;
    }
#endif
    if (edge < vStyle.x) color = vOutline;
    fragColor = color;
#endif
}
