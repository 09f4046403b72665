// The Help window: every key (from the key map, so it cannot drift) and what the mouse does.
#include "app_frame.h"

#include <imgui.h>

void drawHelpWindow(App& app) {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                            ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
    if (!ImGui::Begin("Help", &app.helpOpen, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::End();
        return;
    }
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit;
    if (ImGui::BeginTable("keys", 2, flags)) {
        for (const KeyBinding& b : keyBindings()) {
            if (!b.listed) continue;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(b.keyName);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(b.description);
        }
        const char* mouse[][2] = {
            {"Left click", "Select a block"},
            {"Left drag", "Move a block (the simulation waits; drops beside, never on top)"},
            {"Right drag", "Fling: the arrow is the new velocity"},
            {"Double-click", "Add a block on empty space"},
            {"Wheel", "Zoom about the cursor"},
            {"Middle drag", "Pan"},
        };
        for (const auto& row : mouse) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[0]);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[1]);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}
