// The Help window: every key (from the key map, so it cannot drift), what the mouse does, and
// what each overlay shows (from the overlay table) and how the windows dock. Tabs keep it within
// a 720p screen at UI scale 1.5; a tab longer than the window scrolls.
#include "app_frame.h"
#include "overlay_window.h"

#include <imgui.h>

#include <string>

namespace {

void row(const char* a, const char* b) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(a);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(b);
}

} // namespace

void drawHelpWindow(App& app) {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                            ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f),
                                        ImVec2(io.DisplaySize.x * 0.9f, io.DisplaySize.y * 0.9f));
    ImGui::SetNextWindowBgAlpha(0.98f);
    if (!ImGui::Begin("Help", &app.ui.helpOpen,
                      ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
        ImGui::End();
        return;
    }
    recordShownWindow(app, "Help");
    // The keys named from the key table (input_map.h), as the browser or the window has them.
    const std::string panelKey =
        keyNameOf(app.ui.inBrowser ? Action::NextWindow : Action::KeyboardFocus);
    const std::string intro = keyNameOf(Action::Escape) + " closes this window.  " +
                              keyNameOf(Action::TogglePresent) + ": present mode.  " + panelKey +
                              ": the keyboard to the panel (" + keyNameOf(Action::Escape) +
                              " gives it back).  " +
                              (app.ui.inBrowser ? std::string("Close the tab to quit.")
                                                : keyNameOf(Action::Quit) + " quits.");
    ImGui::TextUnformatted(intro.c_str());
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit;
    if (ImGui::BeginTabBar("help")) {
        if (ImGui::BeginTabItem("Keys")) {
            if (ImGui::BeginTable("keys", 2, flags)) {
                for (const KeyBinding& b : keyBindings()) {
                    const char* what =
                        app.ui.inBrowser && b.inBrowser ? b.inBrowser : b.description;
                    if (b.listed && *what) row(b.keyName, what);
                }
                ImGui::EndTable();
            }
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Mouse")) {
            if (ImGui::BeginTable("mouse", 2, flags)) {
                row("Left click", "Select a block");
                row("Left drag", "Move a block (the simulation waits; drops beside, never on top)");
                row("Right drag", "Fling: the arrow is the new velocity");
                row("Double-click", "Add a block on empty space");
                row("Wheel", "Zoom about the cursor (F fits the world again)");
                row("Middle drag", "Pan");
                ImGui::EndTable();
            }
            ImGui::EndTabItem();
        }
        if (app.ui.touchUi && ImGui::BeginTabItem("Touch")) { // browser/touch_input.h
            if (ImGui::BeginTable("touch", 2, flags)) {
                row("Tap", "Select a block; on the panel, press a button (a number field opens "
                           "for typing: the on-screen keyboard)");
                row("Two quick taps", "Add a block on empty space");
                row("Drag", "Move a block; from empty space, pan the view");
                row("Two fingers", "Pan and zoom");
                row("Swipe on the panel", "Scroll it (a slider under the finger keeps its value)");
                row("Hold, then slide", "Drag a slider");
                ImGui::EndTable();
            }
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Overlays")) {
            dimText("Turn them on in the Overlays section. Windows dock around the scene, which "
                    "keeps the rest; drag a window by its title to float it, \"dock\" puts it "
                    "back.");
            if (ImGui::BeginTable("overlays", 2, flags)) {
                for (const OverlayInfo& o : kOverlays) {
                    row(o.title ? o.title : o.label, o.tooltip);
                }
                ImGui::EndTable();
            }
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    ImGui::End();
}
