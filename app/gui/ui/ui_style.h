// The look of the UI: a dark theme readable on a projector, the font (DejaVu Sans when installed,
// ImGui's built-in font otherwise) and the UI scale. Call between frames, never inside one.
#pragma once

// Creates the ImGui context and sets the theme. `iniPath` null: no ini file (offscreen runs).
void uiCreateContext(const char* iniPath);
void uiDestroyContext();
// Rebuilds the font atlas and style sizes for `scale`. After a change the caller tells the UI
// renderer (uiRendererFontsChanged), which uploads the new atlas at its next NewFrame.
void uiApplyScale(float scale);
// The scale uiApplyScale last applied.
float uiCurrentScale();
