#version 330 core
// Solid triangles take their colour; TEXTURED ones (glyphs, anti-aliased lines) multiply it by
// the font atlas, as ImGui's own renderer does for every triangle.
#ifdef TEXTURED
uniform sampler2D uTexture;
in vec2 vUv;
#endif
in vec4 vColor;
out vec4 fragColor;

void main() {
#ifdef TEXTURED
    fragColor = vColor * texture(uTexture, vUv);
#else
    fragColor = vColor;
#endif
}
