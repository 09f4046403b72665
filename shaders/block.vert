#version 330 core
// Blocks and walls: one instanced unit quad per block or, with POINT_SPRITE defined, one point
// sprite per block (a square big enough to hold it; block.frag discards what lies outside).
// Small blocks are drawn as points: a software rasteriser pays per primitive, and a point is one
// where a quad is two triangles.
#ifndef POINT_SPRITE
layout(location = 0) in vec2 aCorner;   // unit quad corner, each coordinate -1 or +1
#endif
layout(location = 1) in vec4 aRect;     // centre (xy) and half size (zw), metres
layout(location = 2) in vec4 aFill;     // fill colour
layout(location = 3) in vec4 aOutline;  // outline colour
layout(location = 4) in vec2 aStyle;    // x: outline width in pixels, y: pattern (0, 1, 2)

uniform vec4 uTransform;       // clip = world * uTransform.xy + uTransform.zw
uniform float uPixelsPerMetre;

#ifdef POINT_SPRITE
flat out float vPointPx;  // the sprite's side, pixels
#else
out vec2 vLocalPx;   // position inside the quad, pixels from the centre
#endif
flat out vec2 vHalfPx;
flat out vec4 vFill;
flat out vec4 vOutline;
flat out vec2 vStyle;

void main() {
    vHalfPx = aRect.zw * uPixelsPerMetre;
#ifdef POINT_SPRITE
    gl_Position = vec4(aRect.xy * uTransform.xy + uTransform.zw, 0.0, 1.0);
    vPointPx = 2.0 * max(vHalfPx.x, vHalfPx.y) + 2.0;
    gl_PointSize = vPointPx;
#else
    vec2 world = aRect.xy + aCorner * aRect.zw;
    gl_Position = vec4(world * uTransform.xy + uTransform.zw, 0.0, 1.0);
    vLocalPx = aCorner * vHalfPx;
#endif
    vFill = aFill;
    vOutline = aOutline;
    vStyle = aStyle;
}
