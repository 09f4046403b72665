#version 330 core
// Fill with a soft top light and a crisp outline. Variants, chosen by #defines the renderer puts
// after the #version line (one program each, so no pixel pays for a branch it does not take):
//   PATTERNED     the pattern of vStyle.y (1: hatched, for infinite mass at rest; 2: striped,
//                 for kinematic platforms)
//   OUTLINE_ONLY  the outline and nothing inside (the other methods' ghosts)
//   POINT_SPRITE  drawn as a point sprite (see block.vert): the pixels outside the block go
#ifdef POINT_SPRITE
flat in float vPointPx;
#else
in vec2 vLocalPx;
#endif
flat in vec2 vHalfPx;
flat in vec4 vFill;
flat in vec4 vOutline;
flat in vec2 vStyle;

out vec4 fragColor;

void main() {
#ifdef POINT_SPRITE
    // gl_PointCoord runs from 0 to 1 across the sprite, y downwards; at a pixel's centre this
    // is its offset from the block's centre, the same the quad would interpolate.
    vec2 localPx = (gl_PointCoord - 0.5) * vec2(1.0, -1.0) * vPointPx;
    if (abs(localPx.x) > vHalfPx.x || abs(localPx.y) > vHalfPx.y) discard;
#else
    vec2 localPx = vLocalPx;
#endif
    float edge = min(vHalfPx.x - abs(localPx.x), vHalfPx.y - abs(localPx.y));
#ifdef OUTLINE_ONLY
    if (edge >= vStyle.x) discard;
    fragColor = vOutline;
#else
    vec4 color = vFill;
    float shade = 0.92 + 0.08 * (localPx.y / max(vHalfPx.y, 1.0));
    color.rgb *= shade;
#ifdef PATTERNED
    if (vStyle.y > 0.5 && vStyle.y < 1.5) {
        if (mod(localPx.x + localPx.y, 9.0) < 2.5) color.rgb *= 0.72;
    } else if (vStyle.y > 1.5) {
        if (mod(localPx.x - localPx.y, 14.0) < 5.0) color.rgb *= 0.82;
    }
#endif
    if (edge < vStyle.x) color = vOutline;
    fragColor = color;
#endif
}
