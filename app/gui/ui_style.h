// The look of the UI: a dark theme readable on a projector, the font (DejaVu Sans when installed,
// ImGui's built-in font otherwise) and the UI scale. Call between frames, never inside one.
#pragma once

// Creates the ImGui context and sets the theme. `iniPath` null: no ini file (offscreen runs).
void uiCreateContext(const char* iniPath);
void uiDestroyContext();
// Rebuilds the font atlas and style sizes for `scale`. When `rendererReady`, the OpenGL3
// backend's font texture is recreated too.
void uiApplyScale(float scale, bool rendererReady);
// The scale uiApplyScale last applied.
float uiCurrentScale();
// Sets nearest-texel sampling on the backend's font texture (call after the backend's NewFrame,
// which creates it). The atlas maps 1:1 onto the screen, so text looks the same as with linear
// filtering, and llvmpipe shades every ImGui pixel about a third faster (measured: a blended,
// textured full-screen quad 4.1 -> 2.6 ns per pixel).
void uiSharpFontTexture();
