// Methods side by side: the other two methods' blocks drawn as coloured outlines (ghosts) over
// the live world (by the renderer, see appPrepareScene), and a table of each method's statistics:
// collisions, largest overlap, energy, momentum, and how far it has drifted from perfect.
#include "app_frame.h"
#include "number_text.h"
#include "overlay_window.h"
#include "ui_style.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>

namespace {

// An energy in J, kJ or MJ, four significant digits: "2.5 J", "29.17 kJ" (not "2.917e+04 J",
// which no narrow column holds).
std::string energyText(double joules) {
    const char* unit = "J";
    double value = joules;
    for (const char* larger : {"kJ", "MJ", "GJ"}) {
        // (what "%.4g" would write as 1e+04; a blown-up NaN or infinity stays in J as it is)
        if (!(std::abs(value) >= 9999.5) || std::isinf(value)) break;
        value /= 1e3;
        unit = larger;
    }
    char text[64];
    number_text::printGeneral(text, sizeof text, value, 4); // "%.4g"
    return std::string(text) + " " + unit;
}

} // namespace

void drawSideBySideOverlay(App& app) {
    OverlayWindow overlay(app, OverlayId::sideBySide);
    if (!overlay) return;
    const MethodsSideBySide& m = app.sim.run.methods;
    if (!m.running) {
        textWrappedAtSpaces("Starts from the current state when the simulation runs (P or N).");
        return;
    }
    // Each method's row as text: its name, then the statistics (kHeaders' order).
    constexpr int kMethods = static_cast<int>(Method::Count);
    constexpr const char* kHeaders[] = {"method", "collisions",  "max overlap",
                                        "energy", "off perfect", "ms/step"};
    constexpr int kColumns = static_cast<int>(std::size(kHeaders));
    std::string cells[kMethods][kColumns];
    char text[64];
    for (int k = 0; k < kMethods; ++k) {
        const Method method = static_cast<Method>(k);
        const MethodRun& r = m.run(method);
        cells[k][0] = methodName(method);
        cells[k][1] = std::to_string(static_cast<long long>(r.totals.collisions));
        // "%.3g m", "%.3g m", "%.3f" (number_text.h: without printf)
        number_text::printGeneral(text, sizeof text, r.totals.maxPenetration, 3);
        cells[k][2] = std::string(text) + " m";
        cells[k][3] = energyText(r.stats.kineticEnergy + r.stats.potentialEnergy);
        number_text::printGeneral(text, sizeof text, m.divergence(method), 3);
        cells[k][4] = std::string(text) + " m";
        number_text::printFixed(text, sizeof text, r.stats.stepMs, 3);
        cells[k][5] = text;
    }
    const int live = static_cast<int>(app.sim.world().settings.method);
    const ImGuiStyle& st = ImGui::GetStyle();
    const auto width = [&st](const std::string& t) {
        return ImGui::CalcTextSize(t.c_str()).x + 2.0f * st.CellPadding.x + 1.0f; // and a border
    };
    // A row a method, at the width of its contents, where that fits; else (a narrow window) a
    // column a method, its name over two or three lines ("move-and-" / "correct" / "(live)").
    // Never cut, never scrolled sideways.
    float rowsWidth = 0.0f;
    for (int c = 0; c < kColumns; ++c) {
        float widest = width(kHeaders[c]);
        for (int k = 0; k < kMethods; ++k)
            widest = std::max(widest, width(cells[k][c] + (c == 0 && k == live ? " (live)" : "")));
        rowsWidth += widest;
    }
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV;
    const auto methodText = [&](int k, const std::string& t) {
        ImGui::TextColored(uiMarkColorVec(methodMark(static_cast<Method>(k))), "%s", t.c_str());
    };
    if (rowsWidth <= ImGui::GetContentRegionAvail().x) {
        if (ImGui::BeginTable("methods", kColumns, flags)) {
            for (const char* header : kHeaders) ImGui::TableSetupColumn(header);
            ImGui::TableHeadersRow();
            for (int k = 0; k < kMethods; ++k) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                methodText(k, cells[k][0] + (k == live ? " (live)" : ""));
                for (int c = 1; c < kColumns; ++c) {
                    ImGui::TableNextColumn();
                    ImGui::TextUnformatted(cells[k][c].c_str());
                }
            }
            ImGui::EndTable();
        }
    } else if (ImGui::BeginTable("methods", 1 + kMethods, flags)) {
        ImGui::TableSetupColumn("");
        for (int k = 0; k < kMethods; ++k) ImGui::TableSetupColumn(cells[k][0].c_str());
        ImGui::TableNextRow(); // the names: a plain row, so that they size their columns
        ImGui::TableNextColumn();
        for (int k = 0; k < kMethods; ++k) {
            ImGui::TableNextColumn();
            std::string name = cells[k][0];
            const std::size_t dash = name.rfind('-'); // "move-and-" / "correct"
            if (dash != std::string::npos) name.insert(dash + 1, "\n");
            methodText(k, name + (k == live ? "\n(live)" : ""));
        }
        for (int c = 1; c < kColumns; ++c) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(kHeaders[c]);
            for (int k = 0; k < kMethods; ++k) {
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(cells[k][c].c_str());
            }
        }
        ImGui::EndTable();
    }
    // The note where the window has room for it (a short one cuts it, not the table).
    const char* note = "Outlines in the scene: the other methods' blocks.";
    const ImVec2 room = ImGui::GetContentRegionAvail();
    if (ImGui::CalcTextSize(note, nullptr, false, room.x).y <= room.y) dimText(note);
}
