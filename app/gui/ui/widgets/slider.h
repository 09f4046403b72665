// Every slider of the app (the panel's settings, the plots' time window, the timeline's frame, the
// UI scale, the volume) goes through these: ImGui's slider with one rule of ours. ImGui draws the
// handle (its grab) across the track's middle, where the value is written, so that the value's
// digits under it were hard to read ("10▮ s", "0▮50"). Here the handle is a bar along the
// track's bottom edge, under the value's baseline: the value reads whole wherever the handle is.
// The whole track stays the control (a click or a fingertip anywhere on it moves the value), as
// high as before (44 CSS px on a touch screen). Same arguments as ImGui's.
#pragma once

#include <imgui.h>

bool uiSliderFloat(const char* label, float* v, float min, float max, const char* format = "%.3f",
                   ImGuiSliderFlags flags = 0);
bool uiSliderFloat2(const char* label, float v[2], float min, float max,
                    const char* format = "%.3f", ImGuiSliderFlags flags = 0);
bool uiSliderInt(const char* label, int* v, int min, int max, const char* format = "%d",
                 ImGuiSliderFlags flags = 0);
