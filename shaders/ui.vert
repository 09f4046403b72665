#version 330 core
// Dear ImGui's vertices (app/gui/platform/ui_renderer/ui_renderer_gl.cpp). Variant: TEXTURED samples the font atlas.
layout(location = 0) in vec2 aPosition; // px, y down
layout(location = 1) in vec2 aUv;
layout(location = 2) in vec4 aColor;    // normalised from 8 bits per channel

uniform vec4 uTransform; // clip = px * uTransform.xy + uTransform.zw (ImGui's orthographic view)

#ifdef TEXTURED
out vec2 vUv;
#endif
out vec4 vColor;

void main() {
    gl_Position = vec4(aPosition * uTransform.xy + uTransform.zw, 0.0, 1.0);
#ifdef TEXTURED
    vUv = aUv;
#endif
    vColor = aColor;
}
