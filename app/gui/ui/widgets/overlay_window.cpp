#include "overlay_window.h"

#include "imgui_ext.h"
#include "text_format.h"
#include "ui_style.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

namespace {

// Background alpha: opaque, so that nothing of the scene (a grid line, an axis number) shows
// through.
constexpr float kWindowAlpha = 1.0f;

// A box of the world on screen, grown by `grow` px on every side (room for its labels).
ScreenRect screenBox(const App& app, Vec2 centre, Vec2 size, double grow) {
    const Vec2 a = app.view.camera.worldToScreen(centre - size * 0.5);
    const Vec2 b = app.view.camera.worldToScreen(centre + size * 0.5);
    const double x = std::min(a.x, b.x) - grow, y = std::min(a.y, b.y) - grow;
    return {x, y, std::abs(b.x - a.x) + 2.0 * grow, std::abs(b.y - a.y) + 2.0 * grow};
}

// The texts taken on screen (app.ui.takenOnScreen) but the axis numbers, which yield to a plate.
std::vector<ScreenRect> textsNotYielding(const App& app) {
    std::vector<ScreenRect> out;
    for (const ScreenRect& t : app.ui.takenOnScreen.texts)
        if (std::none_of(app.ui.axisNumbers.begin(), app.ui.axisNumbers.end(),
                         [&t](const UiState::AxisNumber& n) {
                             return n.rect.x == t.x && n.rect.y == t.y && n.rect.width == t.width &&
                                    n.rect.height == t.height;
                         }))
            out.push_back(t);
    return out;
}

} // namespace

ImVec2 toScreen(const App& app, Vec2 p) {
    const Vec2 s = app.view.camera.worldToScreen(p);
    return ImVec2(static_cast<float>(s.x), static_cast<float>(s.y));
}

namespace {

// What a caption over the scene avoids (sceneCaptionPlace): the same for every form of it tried.
struct CaptionRoom {
    ScreenRect view, world;
    std::vector<ScreenRect> avoid, texts;
    double inset = 0.0;
};

CaptionRoom captionRoom(const App& app, const std::vector<WorldBox>& boxes) {
    const double font = ImGui::GetFontSize(), s = app.view.uiScale;
    CaptionRoom room;
    room.view = app.view.camera.viewport();
    const ScreenRect& vp = room.view;
    // The status badge along the top of the scene (method, t, PAUSED, the start hint).
    std::vector<ScreenRect>& avoid = room.avoid;
    avoid = {{vp.x, vp.y, vp.width, font + 24.0 * s}};
    // The axis numbers under the world and left of it.
    const ScreenRect w = worldRectOnScreen(app.view.camera, app.sim.world().bounds);
    avoid.push_back({w.x - font, w.y + w.height, w.width + 4.0 * font, 1.6 * font});
    avoid.push_back({w.x - 4.0 * font, w.y - font, 4.0 * font, w.height + 2.0 * font});
    for (const Block& b : app.sim.world().blocks)
        avoid.push_back(screenBox(app, b.position, b.size, font));
    for (const WorldBox& b : boxes) avoid.push_back(screenBox(app, b.centre, b.size, font * 1.5));
    // The magnifiers' insets (magnifier.h), drawn before it.
    for (const DockedWindow& m : app.view.shownMarks)
        if (m.name.rfind("magnifier", 0) == 0) avoid.push_back(m.rect);
    // Where it must cover blocks (a box full of them), it hides none of the texts drawn so far
    // (the labels, the badge: app.ui.takenOnScreen) if it can; the axis numbers yield to it
    // (drawYieldedAxisNumbers leaves out those it covers): their bands above are avoided only.
    room.world = w;
    room.inset = 10.0 * s;
    room.texts = textsNotYielding(app);
    return room;
}

ImVec2 placeIn(const CaptionRoom& room, float width, float height) {
    const ScreenRect r =
        placeCaption(width, height, room.view, room.world, room.avoid, room.inset, room.texts);
    return ImVec2(static_cast<float>(r.x), static_cast<float>(r.y));
}

} // namespace

ImVec2 sceneCaptionPlace(const App& app, float width, float height,
                         const std::vector<WorldBox>& boxes) {
    return placeIn(captionRoom(app, boxes), width, height);
}

namespace {

// The caption's lines wrapped `width` px wide (wrapFormula: never inside a number; kept from
// earlier frames, wrappedFormula), each piece in its line's colour; and the widest piece.
std::vector<CaptionLine> wrappedCaption(const std::vector<CaptionLine>& lines, float width,
                                        float& widest) {
    std::vector<CaptionLine> out;
    widest = 0.0f;
    for (const CaptionLine& l : lines) {
        const std::string& text = wrappedFormula(l.text, width);
        std::size_t start = 0;
        while (start <= text.size()) {
            const std::size_t end = std::min(text.find('\n', start), text.size());
            out.push_back({text.substr(start, end - start), l.color, l.themed});
            widest = std::max(widest, ImGui::CalcTextSize(out.back().text.c_str()).x);
            start = end + 1;
        }
    }
    return out;
}

double overlapArea(const ScreenRect& a, const ScreenRect& b) {
    const double w = std::min(a.x + a.width, b.x + b.width) - std::max(a.x, b.x);
    const double h = std::min(a.y + a.height, b.y + b.height) - std::max(a.y, b.y);
    return w > 0.0 && h > 0.0 ? w * h : 0.0;
}

// What a plate at `at` of `size` hides: the area of the texts taken so far (but the axis
// numbers, which yield) and the magnifiers' insets, then that of the blocks and marks (the point
// of impact's boxes).
struct Hidden {
    double texts = 0.0, blocks = 0.0;
    bool none() const { return texts == 0.0 && blocks == 0.0; }
    bool operator<(const Hidden& o) const {
        return texts < o.texts || (texts == o.texts && blocks < o.blocks);
    }
};
Hidden hiddenBy(const App& app, const std::vector<ScreenRect>& texts, ImVec2 at, ImVec2 size) {
    const ScreenRect plate{at.x, at.y, size.x, size.y};
    Hidden out;
    for (const ScreenRect& t : texts) out.texts += overlapArea(plate, t);
    for (const ScreenRect& b : app.ui.takenOnScreen.blocks) out.blocks += overlapArea(plate, b);
    return out;
}

float widestLine(const std::vector<CaptionLine>& lines) {
    float widest = 0.0f;
    for (const CaptionLine& l : lines)
        widest = std::max(widest, ImGui::CalcTextSize(l.text.c_str()).x);
    return widest;
}

// A caption as drawn: its lines and the widest of them.
struct CaptionForm {
    std::vector<CaptionLine> lines;
    float width = 0.0f;
};

// The forms of a caption tried, in order: as it is where it fits the scene's `room` (px of
// text); its brief form (the lines' `brief`, where any has one), wrapped to the room where even
// that is wider; or, without one, the caption wrapped to the room; then narrower and taller
// (a share of its width: the scene's margin beside the world may hold it). None wider than the
// room, but for a word wider than it.
std::vector<CaptionForm> captionForms(const std::vector<CaptionLine>& lines, float room) {
    std::vector<CaptionLine> brief = lines;
    bool hasBrief = false;
    for (CaptionLine& l : brief)
        if (!l.brief.empty()) {
            l.text = l.brief;
            hasBrief = true;
        }
    std::vector<CaptionForm> forms;
    const auto add = [&forms](const std::vector<CaptionLine>& base, float wrapAt) {
        CaptionForm f;
        f.width = widestLine(base);
        f.lines = wrapAt < f.width ? wrappedCaption(base, wrapAt, f.width) : base;
        forms.push_back(std::move(f));
    };
    const float natural = widestLine(lines);
    if (natural <= room || room <= 0.0f)
        add(lines, natural);
    else if (!hasBrief)
        add(lines, room);
    const std::vector<CaptionLine>& last = hasBrief ? brief : lines;
    const float lastWidth = widestLine(last);
    const float most = room > 0.0f ? std::min(room, lastWidth) : lastWidth;
    if (hasBrief) add(brief, most);
    for (const float share : {0.6f, 0.4f, 0.25f})
        if (lastWidth * share < most) add(last, lastWidth * share);
    return forms;
}

} // namespace

void drawSceneCaption(App& app, const std::vector<CaptionLine>& lines,
                      const std::vector<WorldBox>& boxes) {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const float font = ImGui::GetFontSize();
    const float s = app.view.uiScale;
    // The widest text a plate inside the scene holds: the scene less its margins (10 px x UI
    // scale, placeCaption's inset) and the plate's own (6 px x UI scale on each side). A plate
    // wider than the scene ran under the docked window beside it, its words cut ("crook": step 5
    // of lecture3 at 1280x800, UI 1.5).
    const float room = static_cast<float>(app.view.camera.viewport().width) - 32.0f * s;
    // The first form hiding no text drawn so far and no block, else the one hiding the least.
    const std::vector<CaptionForm> forms = captionForms(lines, room);
    std::size_t chosen = 0;
    ImVec2 plate;
    Hidden least{INFINITY, INFINITY};
    const CaptionRoom place = captionRoom(app, boxes); // the same for every try
    const std::vector<ScreenRect>& texts = place.texts;
    for (std::size_t k = 0; k < forms.size(); ++k) {
        // The plate is 6 px (x UI scale) wider than the text on each side, 4 px taller.
        const ImVec2 size(forms[k].width + 12.0f * s,
                          static_cast<float>(forms[k].lines.size()) * font + 8.0f * s);
        const ImVec2 at = placeIn(place, size.x, size.y);
        const Hidden hidden = hiddenBy(app, texts, at, size);
        if (hidden < least) {
            chosen = k;
            plate = at;
            least = hidden;
        }
        if (hidden.none()) break;
    }
    const std::vector<CaptionLine>& shown = forms[chosen].lines;
    const float width = forms[chosen].width;
    const float n = static_cast<float>(shown.size());
    const ScreenRect taken{plate.x, plate.y, width + 12.0f * s, n * font + 8.0f * s};
    app.ui.captionPlates.push_back(taken);
    // Taken: the labels drawn after it go around it (the point of impact's, placed after its
    // plate so that the plate finds room first).
    app.ui.takenOnScreen.texts.push_back(taken);
    const ImVec2 at(plate.x + 6.0f * s, plate.y + 4.0f * s);
    dl->AddRectFilled(
        ImVec2(at.x - 6 * s, at.y - 4 * s), ImVec2(at.x + width + 6 * s, at.y + n * font + 4 * s),
        uiLightTheme() ? IM_COL32(250, 250, 252, 230) : IM_COL32(16, 18, 26, 215), 4.0f);
    for (std::size_t i = 0; i < shown.size(); ++i)
        dl->AddText(ImVec2(at.x, at.y + static_cast<float>(i) * font),
                    shown[i].themed ? shown[i].color : uiThemed(shown[i].color),
                    shown[i].text.c_str());
}

void recordShownWindow(App& app, const char* name) {
    const ImVec2 p = ImGui::GetWindowPos(), s = ImGui::GetWindowSize();
    app.view.shownWindows.push_back({name, {p.x, p.y, s.x, s.y}});
    // A press in it (or in its child windows): the keyboard moves to it from another window that
    // has it (app_frame.cpp's followKeyboard).
    for (int button = 0; button < 3; ++button)
        if (ImGui::IsMouseClicked(button) && ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows))
            app.ui.clickedWindow = name;
    if (app.ui.keyboardFocus != name) return;
    app.ui.keyboardFocus.clear();
    imgui_ext::focusCurrentWindowForKeyboard();
}

std::string nextWindowForKeyboard(const App& app) {
    // The windows with controls, in this frame's drawing order (the lesson's caption has none).
    std::vector<std::string> windows;
    for (const DockedWindow& w : app.view.shownWindows)
        if (w.name != "Lesson caption") windows.push_back(w.name);
    if (windows.empty()) return "";
    const auto has = std::find(windows.begin(), windows.end(), app.ui.keyboardWindow);
    if (has != windows.end()) return *(has + 1 == windows.end() ? windows.begin() : has + 1);
    const auto panel = std::find(windows.begin(), windows.end(), "Controls");
    return panel != windows.end() ? *panel : windows.front();
}

namespace {

// A folded window's tab: its title, or where the titles do not all fit across the window, its
// overlay's short name (the panel's: "inspector", "cost").
std::string tabLabel(const std::string& title, bool shortName) {
    if (shortName)
        for (const OverlayInfo& row : kOverlays)
            if (row.title && title == row.title) return row.label;
    return title;
}

// The tab bar of the windows folded with `title` (shown), across the top of its window: the
// others' tabs bring theirs to the front (from the next frame); the shown one's closes it.
void drawFoldedTabs(App& app, const DockTabs& tabs, const char* title, bool* open) {
    const ImGuiStyle& st = ImGui::GetStyle();
    // On a touch screen the shown tab has no close button (a font's size: under a fingertip's
    // 44 px); the sheet's overlay switches turn the window off.
    if (app.ui.touchUi) open = nullptr;
    const auto across = [&](bool shortName) {
        // The shown tab's close button.
        float width = open ? ImGui::GetFontSize() + st.FramePadding.x : 0.0f;
        for (const std::string& name : tabs.names)
            width += ImGui::CalcTextSize(tabLabel(name, shortName).c_str()).x +
                     2.0f * st.FramePadding.x + st.ItemInnerSpacing.x;
        return width;
    };
    const bool shortNames = across(false) > ImGui::GetContentRegionAvail().x;
    if (!ImGui::BeginTabBar("##folded", ImGuiTabBarFlags_FittingPolicyResizeDown)) return;
    for (const std::string& name : tabs.names) {
        const std::string label = tabLabel(name, shortNames) + "##" + name;
        if (name == title) {
            if (ImGui::BeginTabItem(label.c_str(), open)) ImGui::EndTabItem();
        } else if (ImGui::TabItemButton(label.c_str())) {
            bringToFront(app.view, name);
        }
        if (ImGui::IsItemHovered() && shortNames) ImGui::SetTooltip("%s", name.c_str());
    }
    ImGui::EndTabBar();
}

} // namespace

bool beginOverlayWindow(App& app, OverlayId id) {
    const OverlayInfo& info = overlayInfo(id);
    const char* title = info.title;
    bool* open = &(app.view.show.*info.flag);
    const ScreenRect* docked = app.view.layout.find(title);
    // Folded with others (DockTabs): a tab bar in place of the title bar.
    const DockTabs* tabs = docked ? app.view.layout.tabsOf(title) : nullptr;
    ImGuiWindowFlags flags = ImGuiWindowFlags_NoSavedSettings;
    if (tabs) flags |= ImGuiWindowFlags_NoTitleBar;
    if (docked) {
        ImGui::SetNextWindowPos(
            ImVec2(static_cast<float>(docked->x), static_cast<float>(docked->y)), ImGuiCond_Always);
        ImGui::SetNextWindowSize(
            ImVec2(static_cast<float>(docked->width), static_cast<float>(docked->height)),
            ImGuiCond_Always);
        ImGui::SetNextWindowCollapsed(false, ImGuiCond_Always);
        flags |= ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;
    }
    ImGui::SetNextWindowBgAlpha(kWindowAlpha);
    const bool visible = ImGui::Begin(title, open, flags);
    recordShownWindow(app, title);
    if (tabs && visible) drawFoldedTabs(app, *tabs, title, open);
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    if (docked) {
        // A press on the title bar, then a drag: the window floats from here on (ImGui moves it
        // with the mouse from the next frame, when the layout no longer places it).
        const bool onTitle =
            io.MousePos.y >= pos.y && io.MousePos.y < pos.y + ImGui::GetFrameHeight();
        std::string& pressed = app.ui.titlePressed;
        if (ImGui::IsWindowHovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && onTitle)
            pressed = title;
        if (pressed == title &&
            ImGui::IsMouseDragging(ImGuiMouseButton_Left, 8.0f * app.view.uiScale)) {
            setFloating(app.view, title, true);
            pressed.clear();
        }
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) pressed.clear();
    } else {
        // Floating: kept on screen, and a button to put it back.
        const ImVec2 display = io.DisplaySize;
        const float keep = 40.0f * app.view.uiScale;
        ImVec2 p = pos;
        p.x = std::clamp(p.x, keep - size.x, display.x - keep);
        p.y = std::clamp(p.y, 0.0f, display.y - ImGui::GetFrameHeight());
        if (p.x != pos.x || p.y != pos.y) ImGui::SetWindowPos(p);
        if (visible) {
            if (uiSmallButton("dock")) setFloating(app.view, title, false);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("Put the window back beside the scene");
        }
    }
    return visible;
}

OverlayWindow::OverlayWindow(App& app, OverlayId id) {
    if (app.view.presentMode) return; // present mode: the scene only
    const char* title = overlayInfo(id).title;
    const DockTabs* tabs = app.view.layout.tabsOf(title);
    if (tabs && tabs->shown != title) return; // folded behind another window's tab
    if (app.view.layout.hides(title)) return; // no room (a phone's open sheet)
    begun_ = true;
    open_ = beginOverlayWindow(app, id);
    // A small docked window (every overlay on at 1280x720) draws its contents in the compact
    // font, baked at its own size (a scaled font would be blurred). Not on a touch screen: its
    // controls would be under a fingertip's 44 px.
    const ScreenRect* docked = app.view.layout.find(overlayInfo(id).title);
    if (open_ && docked && !app.ui.touchUi &&
        compactWindow(docked->width, docked->height, ImGui::GetFontSize())) {
        ImGui::PushFont(uiCompactFont());
        font_ = true;
    }
    if (open_) wholeRows_.emplace();
}

OverlayWindow::~OverlayWindow() {
    if (wholeRows_) wholeRows_->end();
    if (font_) ImGui::PopFont();
    if (begun_) ImGui::End();
}

void drawnByTheSceneRenderer(App&) {}

void drawOverlays(App& app) {
    using Draw = void (*)(App&);
#define SANDBOX_OVERLAY_DRAW(member, name, label, tooltip, on, title, place, draw) draw,
    static constexpr Draw kDraw[] = {SANDBOX_OVERLAYS(SANDBOX_OVERLAY_DRAW)};
#undef SANDBOX_OVERLAY_DRAW
    static_assert(sizeof kDraw / sizeof kDraw[0] == kOverlayCount, "one draw function a row");
    for (std::size_t i = 0; i < kOverlayCount; ++i) {
        if (app.view.show.*kOverlays[i].flag) kDraw[i](app);
    }
}

void dimText(const char* text) {
    const ImVec4 dim =
        uiLightTheme() ? ImVec4(0.32f, 0.35f, 0.42f, 1.0f) : ImVec4(0.62f, 0.66f, 0.74f, 1.0f);
    ImGui::PushStyleColor(ImGuiCol_Text, dim);
    textWrappedFormula(text); // wrapped: a docked window may be narrow, nothing is cut
    ImGui::PopStyleColor();
}
