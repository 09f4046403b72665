// The two dialogs: quitting with unsaved edits (save first, quit anyway, or stay), and Save (the
// file name offered from the scene's name; an existing file is overwritten only by a button that
// says so).
#include "app_frame.h"
#include "overlay_window.h"
#include "ui_style.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <filesystem>

namespace {

constexpr const char* kQuitTitle = "Quit?";
constexpr const char* kSaveTitle = "Save the scene";

bool gQuitAfterSave = false; // the Save dialog was opened from the quit dialog

void centreNext() {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                            ImGuiCond_Always, ImVec2(0.5f, 0.5f));
}

void quitDialog(App& app) {
    if (!app.ui.quitDialogOpen && !ImGui::IsPopupOpen(kQuitTitle)) return;
    if (app.ui.quitDialogOpen && !ImGui::IsPopupOpen(kQuitTitle)) ImGui::OpenPopup(kQuitTitle);
    centreNext();
    if (!ImGui::BeginPopupModal(kQuitTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    recordShownWindow(app, kQuitTitle);
    ImGui::TextUnformatted("This scene has edits that are not saved.");
    if (ImGui::Button("Save first...")) {
        app.ui.quitDialogOpen = false;
        app.ui.saveDialogOpen = true;
        app.ui.saveDialogPath = suggestedSavePath(app);
        gQuitAfterSave = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Quit without saving")) app.ui.quitRequested = true;
    ImGui::SameLine();
    if (ImGui::Button(keyedLabel("Cancel", Action::Escape, app.ui.touchUi).c_str()))
        app.ui.quitDialogOpen = false;
    if (!app.ui.quitDialogOpen) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

void saveDialog(App& app) {
    if (!app.ui.saveDialogOpen && !ImGui::IsPopupOpen(kSaveTitle)) return;
    static bool focus = false;
    if (app.ui.saveDialogOpen && !ImGui::IsPopupOpen(kSaveTitle)) {
        ImGui::OpenPopup(kSaveTitle);
        app.ui.messages.error.clear();
        focus = true;
    }
    centreNext();
    if (!ImGui::BeginPopupModal(kSaveTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    recordShownWindow(app, kSaveTitle);
    ImGui::TextUnformatted("Save the current state as a scene file (format v1):");
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 30.0f);
    if (focus) {
        ImGui::SetKeyboardFocusHere();
        focus = false;
    }
    const bool enter =
        ImGui::InputText("##path", &app.ui.saveDialogPath, ImGuiInputTextFlags_EnterReturnsTrue);
    std::error_code ec;
    const bool exists =
        !app.ui.saveDialogPath.empty() && std::filesystem::exists(app.ui.saveDialogPath, ec);
    if (exists) ImGui::TextColored(uiWarningColor(), "That file exists: Overwrite replaces it.");
    if (!app.ui.messages.error.empty())
        ImGui::TextColored(uiErrorColor(), "%s", app.ui.messages.error.c_str());
    // Enter saves only when nothing would be overwritten: overwriting takes the button.
    if (ImGui::Button(exists ? "Overwrite" : "Save") || (enter && !exists)) {
        if (saveCurrentScene(app, app.ui.saveDialogPath)) {
            app.ui.saveDialogOpen = false;
            if (gQuitAfterSave) app.ui.quitRequested = true;
        }
    }
    ImGui::SameLine();
    if (ImGui::Button(keyedLabel("Cancel", Action::Escape, app.ui.touchUi).c_str()))
        app.ui.saveDialogOpen = false;
    if (!app.ui.saveDialogOpen) {
        gQuitAfterSave = false;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

} // namespace

void drawDialogs(App& app) {
    quitDialog(app);
    saveDialog(app);
}
