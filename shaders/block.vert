#version 330 core
// Blocks and walls: one instanced unit quad per block.
layout(location = 0) in vec2 aCorner;   // unit quad corner, each coordinate -1 or +1
layout(location = 1) in vec4 aRect;     // centre (xy) and half size (zw), metres
layout(location = 2) in vec4 aFill;     // fill colour
layout(location = 3) in vec4 aOutline;  // outline colour
layout(location = 4) in vec2 aStyle;    // x: outline width in pixels, y: pattern (0, 1, 2)

uniform vec4 uTransform;       // clip = world * uTransform.xy + uTransform.zw
uniform float uPixelsPerMetre;

out vec2 vLocalPx;   // position inside the quad, pixels from the centre
flat out vec2 vHalfPx;
flat out vec4 vFill;
flat out vec4 vOutline;
flat out vec2 vStyle;

void main() {
    vec2 world = aRect.xy + aCorner * aRect.zw;
    gl_Position = vec4(world * uTransform.xy + uTransform.zw, 0.0, 1.0);
    vHalfPx = aRect.zw * uPixelsPerMetre;
    vLocalPx = aCorner * vHalfPx;
    vFill = aFill;
    vOutline = aOutline;
    vStyle = aStyle;
}
