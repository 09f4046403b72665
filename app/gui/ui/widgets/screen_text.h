// The screen-text contract (`sandbox-offscreen --text-json`, docs/cli.md): every piece of text
// drawn in a frame, read back from ImGui's draw data after ImGui::Render, so that nothing drawn
// escapes it (panel widgets, windows, the scene's labels, the caption, the badge) and no call
// site has to remember it. ImGui draws a glyph as one quad textured with the glyph's rectangle of
// the font atlas: the quad's texture coordinates name the glyph (and its font), its corners give
// the pen's position and the size it was drawn at. Glyphs drawn one after another (nothing else
// drawn between them) on a line, separated by whole spaces, are one text; a line that starts at
// the text's left edge one line height below continues it (wrapped or "\n"). A glyph cut by its
// draw command's clip rectangle (a window's edge) makes its text "clipped". The same text drawn
// twice one pixel apart (a label's shadow) is listed once.
//
// Which part of the screen a text belongs to: its window's title ("Collision inspector"), with
// the roles named in kTextRoles ("Lesson caption" is "caption", ImGui's background list, where
// the scene draws, is "scene"); a part of a draw list can say its own role (TextRole: the
// status badge, the present mode's caption).
#pragma once

#include "camera.h" // ScreenRect

#include <string>
#include <vector>

struct ImDrawData;
struct ImDrawList;
struct ImFontAtlas;

struct ScreenText {
    std::string text;   // UTF-8; lines joined by "\n"
    ScreenRect rect;    // image pixels from the top-left: the pen's box (line height per line)
    double px = 0.0;    // line height, px (the font's size as drawn)
    std::string window; // "scene", "caption", "status", a window's title, ...
    bool clipped = false;
};

// The texts of `data` (drawn with `atlas`'s fonts), in drawing order.
std::vector<ScreenText> readScreenText(const ImDrawData& data, const ImFontAtlas& atlas);

// {"texts": [{"text": "...", "rect": [x, y, w, h], "px": 24, "window": "scene", "clipped": false},
// ...]}
std::string screenTextJson(const std::vector<ScreenText>& texts);

// What is drawn into `list` while this lives has the role `role` (a string literal), e.g.
// "status". Roles are kept until the next forgetTextRoles (each frame's start).
class TextRole {
  public:
    TextRole(ImDrawList* list, const char* role);
    ~TextRole();
    TextRole(const TextRole&) = delete;
    TextRole& operator=(const TextRole&) = delete;

  private:
    ImDrawList* list_;
    const char* outer_;
};
// The glyphs drawn into `list` between vertex numbers `from` and `to` are of a text wider than
// the room it was given (a wrapped text with a piece no line could hold): their texts are
// "clipped", for ImGui leaves out the glyphs wholly past a window's edge and the draw data alone
// cannot tell that anything is missing.
void markTextOverflowing(const ImDrawList* list, int from, int to);
// Forgets the roles and the overflowing texts (each frame's start).
void forgetTextRoles();
