#include "ui_style.h"

#include "dock_layout.h"
#include "imgui_ext.h"
#include "palette.h"
#include "screen_text.h"
#include "text_format.h"
#include "view.h"
#include "whole_rows.h"

#include <imgui.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <unordered_map>

namespace {

constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr float kUiFontPx = static_cast<float>(kBaseFontPx); // view.h
// The look ImGui's style and fonts are built for: the view's, as uiFollowView last found it (the
// view owns it; this is what the built atlas and style stand for). Scale 0: not built yet.
struct BuiltLook {
    float scale = 0.0f;
    float labelScale = 1.0f;
    bool light = false;
    bool touch = false;
};
BuiltLook gBuilt;
ImFont* gLabelFont = nullptr;
ImFont* gCompactFont = nullptr;
// The classroom's fonts (slideFontPx), baked for the display's height when the look was applied.
ImFont* gCaptionFont = nullptr;
ImFont* gSlideLabelFont = nullptr;
float gSlideCaptionPx = 0.0f, gSlideLabelPx = 0.0f;

bool fileExists(const char* path) {
    if (std::FILE* f = std::fopen(path, "rb")) {
        std::fclose(f);
        return true;
    }
    return false;
}

// What both themes set their own way: the windows' background (the palette's) and one colour for
// the title bars, active or not.
void setWindowColors(ImVec4* c, bool light, const ImVec4& popup, const ImVec4& titleBar) {
    const Color bg = windowBackground(light);
    c[ImGuiCol_WindowBg] = ImVec4(bg.r, bg.g, bg.b, bg.a);
    c[ImGuiCol_PopupBg] = popup;
    c[ImGuiCol_TitleBg] = c[ImGuiCol_TitleBgActive] = c[ImGuiCol_TitleBgCollapsed] = titleBar;
}

// The light theme: ImGui's light colours, windows opaque, the title bars in the same blue.
void setLightColors(ImGuiStyle& style) {
    ImGui::StyleColorsLight(&style);
    ImVec4* c = style.Colors;
    setWindowColors(c, true, ImVec4(0.98f, 0.98f, 0.97f, 0.99f), ImVec4(0.30f, 0.45f, 0.68f, 1.0f));
    c[ImGuiCol_Text] = ImVec4(0.05f, 0.05f, 0.08f, 1.0f);
    c[ImGuiCol_FrameBg] = ImVec4(0.86f, 0.87f, 0.90f, 1.0f);
    c[ImGuiCol_Button] = ImVec4(0.62f, 0.74f, 0.92f, 1.0f);
    c[ImGuiCol_Header] = ImVec4(0.80f, 0.84f, 0.91f, 1.0f);
}

void setTheme(ImGuiStyle& style, bool light) {
    if (light)
        setLightColors(style);
    else
        ImGui::StyleColorsDark(&style);
    style.WindowRounding = 6.0f;
    style.FrameRounding = 4.0f;
    style.GrabRounding = 4.0f;
    style.TabRounding = 4.0f;
    style.WindowBorderSize = 0.0f;
    style.FrameBorderSize = 0.0f;
    style.WindowPadding = ImVec2(12.0f, 10.0f);
    style.FramePadding = ImVec2(8.0f, 4.0f);
    style.ItemSpacing = ImVec2(8.0f, 6.0f);
    style.GrabMinSize = 12.0f;
    // No anti-aliased fringe around filled shapes: it doubled the triangles of the panel, and
    // every thin triangle costs a software rasteriser; rounded corners stay smooth enough.
    style.AntiAliasedFill = false;
    // The keyboard's focus ring: a colour no control has, plainly seen on either theme.
    style.Colors[ImGuiCol_NavHighlight] =
        light ? ImVec4(0.80f, 0.10f, 0.55f, 1.0f) : ImVec4(1.0f, 0.85f, 0.25f, 1.0f);
    if (light) return;
    ImVec4* c = style.Colors;
    setWindowColors(c, false, ImVec4(0.12f, 0.13f, 0.16f, 0.98f),
                    ImVec4(0.16f, 0.29f, 0.48f, 1.0f));
    c[ImGuiCol_Header] = ImVec4(0.20f, 0.25f, 0.33f, 1.0f);
    c[ImGuiCol_HeaderHovered] = ImVec4(0.26f, 0.36f, 0.50f, 1.0f);
    c[ImGuiCol_HeaderActive] = ImVec4(0.30f, 0.42f, 0.60f, 1.0f);
    c[ImGuiCol_FrameBg] = ImVec4(0.17f, 0.19f, 0.24f, 1.0f);
    c[ImGuiCol_FrameBgHovered] = ImVec4(0.22f, 0.25f, 0.32f, 1.0f);
    c[ImGuiCol_FrameBgActive] = ImVec4(0.26f, 0.30f, 0.40f, 1.0f);
    c[ImGuiCol_Button] = ImVec4(0.22f, 0.34f, 0.52f, 1.0f);
    c[ImGuiCol_ButtonHovered] = ImVec4(0.28f, 0.43f, 0.65f, 1.0f);
    c[ImGuiCol_ButtonActive] = ImVec4(0.33f, 0.50f, 0.75f, 1.0f);
    c[ImGuiCol_SliderGrab] = ImVec4(0.45f, 0.65f, 0.95f, 1.0f);
    c[ImGuiCol_SliderGrabActive] = ImVec4(0.60f, 0.78f, 1.0f, 1.0f);
    c[ImGuiCol_CheckMark] = ImVec4(0.60f, 0.80f, 1.0f, 1.0f);
    c[ImGuiCol_Separator] = ImVec4(0.28f, 0.30f, 0.36f, 1.0f);
}

void setTheme(ImGuiStyle& style) {
    setTheme(style, gBuilt.light);
}

// Touch sizes at UI scale 1: a frame kTouchTargetPx high around the 16 px font and as wide
// around a glyph (a window's close button is the font's size plus the frame's padding), a
// slider's grab a fingertip wide, and a scroll bar a finger can hold (a swipe scrolls too).
void setTouchSizes(ImGuiStyle& style) {
    const float pad = (kTouchTargetPx - kUiFontPx) * 0.5f;
    style.FramePadding = ImVec2(pad, pad);
    style.ItemSpacing = ImVec2(10.0f, 8.0f);
    style.ItemInnerSpacing = ImVec2(8.0f, 6.0f);
    style.GrabMinSize = 28.0f;
    style.ScrollbarSize = kTouchTargetPx;
}

} // namespace

void uiCreateContext(const char* iniPath) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = iniPath;
    // Every control reachable from the keyboard once a window has it (F6, Tab or a click in it):
    // the arrows move ImGui's focus ring, Space presses, Enter types into a field. Until then the
    // scene has the keyboard and the navigation is off (app_frame.cpp's followKeyboard).
    io.ConfigFlags &= ~ImGuiConfigFlags_NavEnableKeyboard;
    imgui_ext::mapKeys(); // the navigation's keys
    setTheme(ImGui::GetStyle());
    gBuilt = BuiltLook{};
    gLabelFont = nullptr;
    gCompactFont = nullptr;
    gCaptionFont = gSlideLabelFont = nullptr;
    gSlideCaptionPx = gSlideLabelPx = 0.0f;
}

void uiDestroyContext() {
    ImGui::DestroyContext();
}

ImFont* addFont(ImGuiIO& io, float px) {
    if (fileExists(kFontPath)) {
        // Glyphs baked at their screen size and snapped to whole pixels: the atlas maps 1:1 onto
        // the screen, so it can be sampled with the nearest texel (see ui_renderer_gl.cpp).
        ImFontConfig config;
        config.OversampleH = 1;
        config.OversampleV = 1;
        config.PixelSnapH = true;
        return io.Fonts->AddFontFromFileTTF(kFontPath, px, &config);
    }
    ImFontConfig config;
    config.SizePixels = px * 13.0f / kUiFontPx;
    return io.Fonts->AddFontDefault(&config);
}

namespace {

void applyStyle(const BuiltLook& look) {
    ImGuiStyle style;
    setTheme(style, look.light);
    if (look.touch) setTouchSizes(style);
    style.ScaleAllSizes(look.scale);
    // ImGui's scroll bar takes its grab 3 px (pixels, not scaled) in from each side of its track:
    // on a touch screen the part a finger can hold is the track's size less those.
    if (look.touch) style.ScrollbarSize += 6.0f;
    ImGui::GetStyle() = style;
}

float slideFontPx(double share, float atLeast) {
    const float height = ImGui::GetIO().DisplaySize.y;
    const float px = height > 0.0f ? static_cast<float>(std::ceil(share * height)) : 0.0f;
    return std::fmax(px, std::round(atLeast));
}

// The classroom's fonts for the display's height at `look`.
float captionPx(const BuiltLook& look) {
    return slideFontPx(kCaptionShare, kUiFontPx * look.scale);
}
float slideLabelPx(const BuiltLook& look) { // one formula with the camera's fit (view.h)
    return static_cast<float>(
        sceneLabelPx(look.scale, look.labelScale, ImGui::GetIO().DisplaySize.y));
}

} // namespace

bool uiFollowView(const View& view, bool touch) {
    const BuiltLook look{view.uiScale, view.labelScale, view.lightTheme, touch};
    // The classroom's text, whatever the UI scale (never smaller than the UI's own).
    const bool fonts = look.scale != gBuilt.scale || look.labelScale != gBuilt.labelScale ||
                       !gLabelFont || captionPx(look) != gSlideCaptionPx ||
                       slideLabelPx(look) != gSlideLabelPx;
    if (!fonts && look.light == gBuilt.light && look.touch == gBuilt.touch) return false;
    gBuilt = look;
    if (fonts) {
        const float scale = look.scale, labelScale = look.labelScale;
        ImGuiIO& io = ImGui::GetIO();
        io.Fonts->Clear();
        addFont(io, kUiFontPx * scale); // the first font is ImGui's default: the UI's
        // The scene's labels: a font of their own size (a scaled UI font would be blurred).
        gLabelFont = labelScale == 1.0f ? io.Fonts->Fonts[0]
                                        : addFont(io, std::round(kUiFontPx * scale * labelScale));
        gCompactFont =
            addFont(io, std::round(kUiFontPx * scale * static_cast<float>(kCompactFontScale)));
        gSlideCaptionPx = captionPx(look);
        gSlideLabelPx = slideLabelPx(look);
        gCaptionFont = addFont(io, gSlideCaptionPx);
        gSlideLabelFont = addFont(io, gSlideLabelPx);
        io.Fonts->Build();
    }
    applyStyle(look);
    return fonts;
}

void uiBeginRows() {
    const float row = kTouchTargetPx * gBuilt.scale - ImGui::GetTextLineHeight();
    const ImVec2 spacing = ImGui::GetStyle().ItemSpacing;
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing,
                        gBuilt.touch ? ImVec2(spacing.x, std::fmax(spacing.y, row)) : spacing);
}

void uiEndRows() {
    ImGui::PopStyleVar();
}

bool uiSmallButton(const char* label) {
    if (gBuilt.touch) return ImGui::Button(label);
    // ImGui's SmallButton has no vertical padding: its label is clipped to the line, and a
    // large font's descenders ("velocity", "energy" at UI scale 1.5) were cut. Two pixels more.
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(ImGui::GetStyle().FramePadding.x, 1.0f));
    const bool pressed = ImGui::Button(label);
    ImGui::PopStyleVar();
    return pressed;
}

ImFont* uiCompactFont() {
    return gCompactFont ? gCompactFont : ImGui::GetFont();
}

ImFont* uiLabelFont() {
    return gLabelFont ? gLabelFont : ImGui::GetFont();
}

ImFont* uiCaptionFont() {
    return gCaptionFont ? gCaptionFont : ImGui::GetFont();
}

ImFont* uiSlideLabelFont() {
    return gSlideLabelFont ? gSlideLabelFont : uiLabelFont();
}

bool uiLightTheme() {
    return gBuilt.light;
}

ImVec4 uiThemed(const ImVec4& c) {
    if (!gBuilt.light) return c;
    float h = 0.0f, s = 0.0f, v = 0.0f;
    ImGui::ColorConvertRGBtoHSV(c.x, c.y, c.z, h, s, v);
    if (s < 0.25f) {
        v = std::fmin(0.45f, std::fmax(0.08f, 1.05f - v)); // white near black, grey darker
    } else {
        s = std::fmax(s, 0.7f);
        v = std::fmin(v, 0.6f);
    }
    ImVec4 out(0.0f, 0.0f, 0.0f, c.w);
    ImGui::ColorConvertHSVtoRGB(h, s, v, out.x, out.y, out.z);
    return out;
}

ImU32 uiThemed(ImU32 c) {
    if (!gBuilt.light) return c;
    return ImGui::ColorConvertFloat4ToU32(uiThemed(ImGui::ColorConvertU32ToFloat4(c)));
}

namespace {

// Wrapped texts as earlier frames made them, by what the wrapping depends on: the text, the
// width, the rule (at spaces or a formula's) and the font (its size too). Most of the UI's text
// is the same from one frame to the next, and wrapping it measures every word. A running number
// makes a new text each frame: when the memo holds kMaxWrapped texts it becomes the older one,
// and the texts still in use move back from it as they are asked for (the rest go at the next
// turn), so the steady texts are never wrapped again.
constexpr std::size_t kMaxWrapped = 512;
std::unordered_map<std::string, std::string> gWrapped, gWrappedBefore;

const std::string& wrapped(const std::string& text, float width, bool formula) {
    const ImFont* font = ImGui::GetFont();
    const float size = ImGui::GetFontSize();
    std::string key(reinterpret_cast<const char*>(&font), sizeof font);
    key.append(reinterpret_cast<const char*>(&size), sizeof size);
    key.append(reinterpret_cast<const char*>(&width), sizeof width);
    key += formula ? 'f' : 's';
    key += text;
    const auto found = gWrapped.find(key);
    if (found != gWrapped.end()) return found->second;
    if (gWrapped.size() >= kMaxWrapped) {
        gWrappedBefore.swap(gWrapped);
        gWrapped.clear();
    }
    const auto before = gWrappedBefore.find(key);
    if (before != gWrappedBefore.end()) return gWrapped[std::move(key)] = std::move(before->second);
    const auto measure = [](const std::string& line) {
        return static_cast<double>(ImGui::CalcTextSize(line.c_str()).x);
    };
    return gWrapped[std::move(key)] =
               formula ? wrapFormula(text, width, measure) : wrapAtSpaces(text, width, measure);
}

} // namespace

const std::string& wrappedAtSpaces(const std::string& text, float width) {
    return wrapped(text, width, false);
}

const std::string& wrappedFormula(const std::string& text, float width) {
    return wrapped(text, width, true);
}

namespace {

// A wrapped text's lines: one row for a region that shows whole rows (an equation is not shown
// without its result). Wider than `width` (a piece no line could hold), it is marked as cut.
void textLines(const std::string& lines, float width) {
    ImDrawList* list = ImGui::GetWindowDrawList();
    const int from = imgui_ext::drawListVertices(*list);
    ImGui::TextUnformatted(lines.c_str(), lines.c_str() + lines.size());
    constexpr float kSlack = 0.5f; // px: float rounding
    if (ImGui::GetItemRectSize().x > width + kSlack)
        markTextOverflowing(list, from, imgui_ext::drawListVertices(*list));
    if (lines.find('\n') != std::string::npos)
        WholeRows::keepTogether(ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
}

} // namespace

void textWrappedAtSpaces(const std::string& text) {
    const float width = ImGui::GetContentRegionAvail().x;
    textLines(wrapped(text, width, false), width);
}

void textWrappedFormula(const std::string& text) {
    const float width = ImGui::GetContentRegionAvail().x;
    textLines(wrapped(text, width, true), width);
}

void wrappedTooltip(const std::string& text) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text.c_str(), text.c_str() + text.size());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

ImVec4 uiErrorColor() {
    return uiThemed(ImVec4{1.0f, 0.45f, 0.42f, 1.0f});
}
ImVec4 uiWarningColor() {
    return uiThemed(ImVec4{1.0f, 0.76f, 0.28f, 1.0f});
}
ImVec4 uiNoteColor() {
    return uiThemed(ImVec4{0.55f, 0.85f, 0.60f, 1.0f});
}
ImVec4 uiDimColor() {
    return uiThemed(ImVec4{0.62f, 0.66f, 0.74f, 1.0f});
}
ImVec4 uiQuestionColor() {
    return uiThemed(ImVec4{1.0f, 0.82f, 0.40f, 1.0f});
}

ImVec4 uiMarkColorVec(Mark mark) {
    const Color c = markColor(mark, gBuilt.light);
    return ImVec4(c.r, c.g, c.b, c.a);
}

ImU32 uiMarkColor(Mark mark) {
    return markColor(mark, gBuilt.light).packed();
}
