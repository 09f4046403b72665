// The look of the UI: a dark theme readable on a projector, the font (DejaVu Sans when installed,
// ImGui's built-in font otherwise) and the UI scale. Call between frames, never inside one.
#pragma once

#include <string>

struct View;

// Creates the ImGui context and sets the theme. `iniPath` null: no ini file (offscreen runs).
void uiCreateContext(const char* iniPath);
void uiDestroyContext();
// The look is the view's (its UI scale, the scene labels' size, the dark or light theme) with the
// app's touch sizes (App::ui.touchUi): each main calls this between frames, every frame, and it
// rebuilds what changed since: the font atlas and style sizes for the UI scale, the labels' font
// at labelScale times the UI font, the classroom's fonts for the display's height, the theme,
// the touch sizes. True when the fonts changed: the caller then tells the UI renderer
// (uiRendererFontsChanged), which uploads the new atlas at its next NewFrame.
bool uiFollowView(const View& view, bool touch);
// Sizes for fingers (phones and tablets; the browser build when the device has a touch screen):
// every button, field, checkbox and header at least kTouchTargetPx high (at UI scale 1), the
// platforms' guideline for a tap target (Apple: 44 pt; Material: 48 dp), and the rows of lists
// as tall.
constexpr float kTouchTargetPx = 44.0f;
// In a list (a combo's popup, the lesson's steps): rows kTouchTargetPx high with touch sizes.
void uiBeginRows();
void uiEndRows();
// ImGui::SmallButton, but a full-height button with touch sizes.
bool uiSmallButton(const char* label);
// The font of the scene's labels (block names, axis numbers, the caption): its own size.
struct ImFont;
ImFont* uiLabelFont();
// The classroom's text (a lesson, present mode): sized by the window's height whatever the UI
// scale, as a slide's text is (a slide's body text is about 4% of its height): the caption bar's
// (title, caption, question or answer, method and t) kCaptionShare of it, 36 px at 1080, the
// scene's labels kSceneLabelShare (view.h), 24 px at 1080; never smaller than the UI's own fonts.
// Baked for the display's height (ImGui's DisplaySize) by uiFollowView, again when the height
// changes.
constexpr double kCaptionShare = 0.033;
ImFont* uiCaptionFont();
ImFont* uiSlideLabelFont();
// The font of small docked windows (compactWindow in dock_layout.h): kCompactFontScale of the UI
// font's size.
ImFont* uiCompactFont();
bool uiLightTheme();
// ImGui::TextWrapped, but broken at spaces only (wrapAtSpaces): "58.152" stays one piece.
void textWrappedAtSpaces(const std::string& text);
// `text` wrapped at spaces to `width` in the current font, as textWrappedAtSpaces shows it (kept
// from earlier frames: the same text, width and font are not wrapped again). Valid until the
// next wrapping.
const std::string& wrappedAtSpaces(const std::string& text, float width);
// A line with equations, wrapped before its operators (wrapFormula): nothing cut at the window's
// edge, and each chain still reads as one.
void textWrappedFormula(const std::string& text);
// `text` wrapped as a formula (wrapFormula) to `width` in the current font, kept as
// wrappedAtSpaces keeps its texts. Valid until the next wrapping.
const std::string& wrappedFormula(const std::string& text, float width);
// The last item's tooltip while it is hovered: `text`, wrapped 30 font sizes wide (the whole of
// what the item shows shortened).
void wrappedTooltip(const std::string& text);
// A colour chosen for the dark theme (text, lines and marks over a dark background), as the
// current theme draws it: itself in the dark theme; in the light one a dark tone of the same hue
// (bright colours deepened, greys and white turned dark), alpha kept, so it reads on light.
using ImU32 = unsigned int;
struct ImVec4;
ImU32 uiThemed(ImU32 darkThemeColor);
ImVec4 uiThemed(const ImVec4& darkThemeColor);
// The panels' text colours, one per role (each uiThemed): a failed load or save, a refused value
// or an existing file, a note or a lesson's answer, a hint, a lesson's question.
ImVec4 uiErrorColor();
ImVec4 uiWarningColor();
ImVec4 uiNoteColor();
ImVec4 uiDimColor();
ImVec4 uiQuestionColor();
// A mark's colour in the current theme (palette.h's table: chosen per theme, not uiThemed).
enum class Mark;
ImU32 uiMarkColor(Mark mark);
ImVec4 uiMarkColorVec(Mark mark);
