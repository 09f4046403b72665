#include "slider.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace {

// While it lives, the sliders drawn into the current window have their handles moved under their
// value: each vertex of the grab's colours drawn since it was made is moved from the grab's height
// (the track less ImGui's 2 px at the top and the bottom) into the bar under the value's baseline.
class HandleUnderValue {
  public:
    HandleUnderValue() : list_(ImGui::GetWindowDrawList()), from_(list_->VtxBuffer.Size) {}
    ~HandleUnderValue() {
        constexpr float kGrabPadding = 2.0f; // ImGui's, between the track's edge and its grab
        const float top = ImGui::GetItemRectMin().y, bottom = ImGui::GetItemRectMax().y;
        const float grabTop = top + kGrabPadding, grabBottom = bottom - kGrabPadding;
        if (grabBottom <= grabTop) return;
        // The value is centred in the track on one line; its digits end at the font's baseline.
        const ImFont* font = ImGui::GetFont();
        const float textTop = std::floor(top + (bottom - top - ImGui::GetFontSize()) * 0.5f);
        const float barBottom = grabBottom;
        const float barTop = std::min(textTop + std::ceil(font->Ascent) + 1.0f, barBottom - 2.0f);
        const float scale = (barBottom - barTop) / (grabBottom - grabTop);
        const ImU32 grab = ImGui::GetColorU32(ImGuiCol_SliderGrab);
        const ImU32 active = ImGui::GetColorU32(ImGuiCol_SliderGrabActive);
        for (int i = from_; i < list_->VtxBuffer.Size; ++i) {
            ImDrawVert& v = list_->VtxBuffer[i];
            if (v.col != grab && v.col != active) continue;
            v.pos.y = barTop + (std::clamp(v.pos.y, grabTop, grabBottom) - grabTop) * scale;
        }
    }
    HandleUnderValue(const HandleUnderValue&) = delete;
    HandleUnderValue& operator=(const HandleUnderValue&) = delete;

  private:
    ImDrawList* list_;
    int from_;
};

} // namespace

bool uiSliderFloat(const char* label, float* v, float min, float max, const char* format,
                   ImGuiSliderFlags flags) {
    const HandleUnderValue handle;
    return ImGui::SliderFloat(label, v, min, max, format, flags);
}

bool uiSliderFloat2(const char* label, float v[2], float min, float max, const char* format,
                    ImGuiSliderFlags flags) {
    const HandleUnderValue handle;
    return ImGui::SliderFloat2(label, v, min, max, format, flags);
}

bool uiSliderInt(const char* label, int* v, int min, int max, const char* format,
                 ImGuiSliderFlags flags) {
    const HandleUnderValue handle;
    return ImGui::SliderInt(label, v, min, max, format, flags);
}
