// Dear ImGui beyond its public API, in one place: everything the app takes from ImGui's
// internals (its internal header), from its legacy input fields (1.86 has no input events: the keys
// are io.KeysDown indexed by GLFW's key codes, mapped by io.KeyMap; the pointer is io.MousePos)
// and from its draw lists read back after drawing (the rows a scroll region cuts, the texts on
// screen). Written against Dear ImGui 1.86 (IMGUI_VERSION_NUM 18600: Debian 12's, and the
// browser build's, compiled from Debian's source package); imgui_ext.cpp refuses to compile
// against another version, so an upgrade starts here and touches no other file.
#pragma once

#include "input_map.h" // KeyPress

#include <imgui.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace imgui_ext {

// --- Keys and pointer (legacy input) ---

// ImGui's navigation and text fields read the keys by GLFW's codes (input_map.h's keys::), as
// its GLFW backend writes them: arrows, Tab, Space, Enter, Esc, Home, End, Delete; not PageUp
// and PageDown, which are the lesson's and never move ImGui's focus.
void mapKeys();
// Whether ImGui sees the key (a GLFW key code) held in this frame.
bool keyDown(int key);
// ImGui 1.86 reads the keys held at the start of a frame, so a tap between two frames (a quick
// key press, a test's) is lost to its keyboard navigation. Before ImGui::NewFrame(): the keys of
// `queued` (presses not yet taken) are held down for this frame; `held` remembers them, and the
// next call lets them go (back to `isDown`, the key's real state).
void holdKeyTaps(const std::vector<KeyPress>& queued, std::vector<int>& held,
                 const std::function<bool(int key)>& isDown);
// The pointer as a finger moves it (touch_input.h), before ImGui::NewFrame(): at `pos` (nowhere:
// nothing hovered, so no tooltip stays), the left button `down`, Ctrl held when `ctrl` or a Ctrl
// key is down.
void setPointer(bool onScreen, ImVec2 pos, bool down, bool ctrl);

// --- Keyboard navigation ---

// The current window (between Begin and End) takes the keyboard: ImGui's navigation focuses it
// and its first control, with the focus ring shown (as after an arrow key) and the mouse's hover
// off until the mouse moves.
void focusCurrentWindowForKeyboard();
// Ends the typing into the active text field (a Ctrl+clicked slider, a file name), keeping what
// was typed (as a click elsewhere does).
void stopTyping();
// After ImGui::Render: whether a text field had the keyboard in this frame or takes it in the
// next (ImGui then asks the platform for the clipboard: the window's loop builds such frames on
// its main thread).
bool typingAfterFrame();
// After an exception left an ImGui frame open (the browser's frame goes on after an error): its
// windows and stacks are closed as ImGui's own error recovery does, and the frame ended.
void endFrameLeftOpen();
// Where the keyboard's focus is: the control's id (0: none), whether its ring shows and its
// rectangle (screen pixels, where the ring is drawn).
struct KeyboardFocus {
    unsigned id = 0;
    bool ringShown = false;
    ImVec2 min, max;
};
KeyboardFocus keyboardFocus();
// A child window's flag: the arrow keys go on from the parent's controls into the child's (no
// key needed to enter it).
ImGuiWindowFlags flattenedNavigation();

// --- Touch scrolling ---

// The window a swipe from the pointer scrolls: the nearest one under it that scrolls (from the
// hovered child outward); none when the pointer is over no window.
struct ScrollTarget {
    void* window = nullptr;
};
ScrollTarget scrollTargetUnderPointer();
// Scrolls `target` by `dy` pixels (down: positive).
void scrollBy(ScrollTarget target, float dy);

// --- What was drawn (the draw lists read back) ---

// A place in the current window's draw list; what is drawn after it can be read and clipped.
struct DrawMark {
    ImDrawList* list = nullptr;
    int command = 0; // the command being drawn into at the mark
    int index = 0;   // the first index drawn after the mark
};
DrawMark markDrawing();
// Whether the current window still draws where `mark` was made.
bool stillDrawing(const DrawMark& mark);
// The vertical extent of each triangle drawn into the current window since `mark` (none when
// the current window draws into another list), leaving out those of colour `skip` (alpha
// ignored), given in drawing order (screen pixels) to `into`.
struct Span {
    float y0, y1;
};
// Spans taken in the order they come, as rows are gathered (WholeRows::rowsOf): one `tall` or
// taller left out, one that meets the last kept (each starts at most `slack` below the other's
// end) merged into it. A line of text, a hundred triangles, is then a span or so.
struct MergedSpans {
    explicit MergedSpans(float tallest) : tall(tallest) {}
    float tall;
    float slack = 0.5f; // px
    std::vector<Span> spans;
    void add(const Span& s) {
        if (s.y1 - s.y0 >= tall) return;
        if (!spans.empty()) {
            Span& last = spans.back();
            if (s.y0 <= last.y1 + slack && last.y0 <= s.y1 + slack) {
                last.y0 = std::min(last.y0, s.y0);
                last.y1 = std::max(last.y1, s.y1);
                return;
            }
        }
        spans.push_back(s);
    }
};
void drawnSince(const DrawMark& mark, ImU32 skip, MergedSpans& into);
// Narrows what was drawn into the current window since `mark` to the band from `top` to
// `bottom` (screen pixels): nothing of it shows outside.
void clipDrawnSince(const DrawMark& mark, float top, float bottom);
// The mouse over `min`-`max` (screen pixels) of the current window reaches none of the controls
// submitted after this call: the rectangle takes the hover (and is no stop of the keyboard).
void takeHover(ImVec2 min, ImVec2 max);

// The part of the screen a draw list belongs to, as ImGui names it: a window's title ("title##id"
// included; "Parent/Child_1A2B" for a child), "##Background", "##Foreground", "##Tooltip_00".
std::string drawListOwner(const ImDrawList& list);
// How many vertices `list` holds so far (a TextRole's place in it).
int drawListVertices(const ImDrawList& list);
// A rectangle drawn with a texture, axis-aligned, as ImGui draws a glyph: its corners on screen
// and in the texture, its draw command's clip rectangle (x0, y0, x1, y1) and its first vertex.
struct DrawnRect {
    ImVec2 min, max, uvMin, uvMax;
    ImVec4 clip;
    int vertex = 0;
};
// Every rectangle drawn into `list` with `texture`, in drawing order; between them `other()`
// for anything else drawn (a frame's triangles) and at each new draw command.
void forEachDrawnRect(const ImDrawList& list, ImTextureID texture,
                      const std::function<void(const DrawnRect&)>& rect,
                      const std::function<void()>& other);

// A window, or a part of one (a child window, a table's scrolling part), whose content is wider
// than it shows: a reader must scroll it sideways. `window` is its root window's title (the part
// before any "##"), `min`-`max` the part on screen and `hidden` how many pixels it hides.
struct SidewaysScroll {
    std::string window;
    ImVec2 min, max;
    float hidden = 0.0f;
};
// Those of the frame drawn last (the windows active in it), in ImGui's order of windows.
std::vector<SidewaysScroll> sidewaysScrolls();

// --- The controls of a frame (the browser build's tests) ---

// An interactive item ImGui added (a button, a slider, a window's close button, ...): its label's
// shown part ("Play##bar": "Play"; "" for none), its root window's name, its rectangle on screen
// and whether some of it is inside its window's clipping rectangle.
struct ItemSeen {
    ImGuiID id = 0;
    std::string label;
    std::string window;
    ImVec2 min, max;
    bool visible = false;
};
struct ItemsOfAFrame {
    std::vector<ItemSeen> items;     // of the windows shown, in the order added
    float narrowestScrollbar = 0.0f; // the width of the narrowest scrollbar shown (0: none)
};
// The last whole frame's items, through ImGui's test-engine item hooks: compiled in only where
// ImGui is built with IMGUI_ENABLE_TEST_ENGINE (the browser build, cmake/web.cmake); elsewhere
// always empty. The first call turns the hooks on (until then an item costs ImGui a flag's
// test), so its answer is empty until a frame has been drawn since.
const ItemsOfAFrame& itemsOfLastFrame();

} // namespace imgui_ext
