// The keyboard map: which key does what (the lecture's debug keys and the sandbox's own), as pure
// data and one function, so the Help window and the tests read the same table.
#pragma once

#include "vec2.h"

#include <functional>
#include <string>
#include <vector>

// Key codes are GLFW's: ImGui 1.86 with its GLFW backend indexes io.KeysDown by them, and the
// offscreen renderer uses the same codes. window_glfw.cpp checks they match <GLFW/glfw3.h>.
namespace keys {
// Printable keys are their ASCII codes (a letter's upper case); GLFW numbers the others from 256.
constexpr int kSpace = ' ', kMinus = '-', kEqual = '=';
constexpr int k0 = '0'; // k0 + d for the digit d
constexpr int kA = 'A', kC = 'C', kD = 'D', kF = 'F', kM = 'M', kN = 'N', kP = 'P', kQ = 'Q',
              kR = 'R', kS = 'S', kU = 'U', kV = 'V', kY = 'Y', kZ = 'Z';
constexpr int kEscape = 256, kEnter = 257, kTab = 258, kDelete = 261;
constexpr int kRight = 262, kLeft = 263, kDown = 264, kUp = 265;
constexpr int kPageUp = 266, kPageDown = 267, kHome = 268, kEnd = 269;
constexpr int kF1 = 290, kF5 = 294, kF6 = 295, kF11 = 300;
constexpr int kKeypad0 = 320; // kKeypad0 + d for the digit d
constexpr int kKeypadSubtract = 333, kKeypadAdd = 334, kKeypadEnter = 335;
constexpr int kLeftControl = 341, kRightControl = 345;
} // namespace keys

enum class Action {
    None,
    Reset,            // R: blocks and time back to the scene as loaded; settings kept
    ResetToFile,      // Shift+R: everything back to the scene as loaded
    TogglePause,      // P
    ToggleSlowMotion, // Space: 5 simulation frames per second, as in the lecture's demo
    ToggleTrails,     // D: draw trajectories
    ClearTrails,      // C: clear trajectories
    CycleMethod,      // S: perfect -> move-and-correct -> turn-based
    StepOnce,         // N: one frame (pauses)
    ToggleVectors,    // V: velocity arrows
    ToggleFrame,      // U: the centre-of-mass frame (the camera moves with u) or the world's
    FitView,          // F: show the whole world
    ToggleSound,      // M: a knock at each collision (off by default outside lessons)
    TogglePresent,    // F5: present mode (the scene and a caption only), as slides start
    KeyboardFocus,    // Tab: the panel takes the keyboard (ImGui's navigation, a focus ring)
    NextWindow,       // F6: the next window takes the keyboard (panel, overlays, Help)
    Navigate,         // arrows, Space, Enter while a window has the keyboard: ImGui's (routeKey)
    ToggleFullscreen, // F11
    ToggleHelp,       // F1
    UiScaleUp,        // Ctrl+=
    UiScaleDown,      // Ctrl+-
    DeleteSelected,   // Delete
    Escape,           // Esc: closes a dialog or Help, leaves present mode or fullscreen
    Quit,             // Ctrl+Q (asks when there are unsaved edits)
    Save,             // Ctrl+S: save the current state as a scene (asks for a name)
    Undo,             // Ctrl+Z: the last edit taken back (docs/edits.md)
    Redo,             // Ctrl+Shift+Z, Ctrl+Y: the last undone edit done again
    LessonNext,       // PageDown, Right: the answer, or the next step of the lesson
    LessonPrevious,   // PageUp, Left
    LessonFirst,      // Home
    LessonLast,       // End
    LessonDigit,      // 0-9: a step number (digitOfKey), then...
    LessonJump,       // Enter: go to it
    // Thrust on (the Physics section): the arrow keys push the selected block while held. The
    // frame reads which are down (heldThrustDirection); a press itself does nothing.
    ThrustLeft,
    ThrustRight,
    ThrustDown,
    ThrustUp,
    TogglePoll, // A: the class poll on / off for the open lesson (docs/poll.md)
};

// When a binding holds: always, or only with thrust off or on (the arrow keys step the lesson
// with thrust off and push the selected block with it on).
enum class KeyWhen { Always, ThrustOff, ThrustOn };

// A key press as the window reports it (queued by the window backend, so a tap shorter than a
// frame is not lost: ImGui 1.86 only sees keys still down at the start of a frame).
struct KeyPress {
    int key;
    bool ctrl;
    bool shift = false;
};

struct KeyBinding {
    int key;
    bool ctrl;
    Action action;
    const char* keyName;     // as shown in the Help window
    const char* description; // as shown in the Help window
    bool listed = true;      // in the Help window (one row stands for the ten digit keys)
    bool shift = false;
    KeyWhen when = KeyWhen::Always;
    // In the browser build: nullptr, the same; otherwise the key is the browser's own (not bound)
    // and this is what Help says of it ("": not listed).
    const char* inBrowser = nullptr;
};

// Every binding, in the order the Help window lists them.
const std::vector<KeyBinding>& keyBindings();
// Where a key press goes. The scene has the keyboard until a window is asked to take it (F6, or
// Tab in the window); a click on a slider or a field works it with the mouse and leaves the
// keyboard to the scene. While a window has the keyboard, ImGui's keyboard navigation is on
// (`navigation`) and takes the keys that move its focus ring (arrows, Tab, Home, End), and Space
// and Enter while the ring shows (`ring`: they press or type into the control it is on).
// Everything else is the table's, whatever has the keyboard: PageDown, PageUp, the digits, P, R,
// S, F5, Esc (which gives the keyboard back to the scene) and the rest. While a text field takes
// typing (`typing`: a Ctrl+click on a slider, a file name), the keys that type or edit text
// (letters, digits, Space, Enter, the arrows, Home, End, Delete, Tab) are the field's and the
// keys that cannot type are the table's (keepsWhileTyping).
enum class KeyRoute { Table, Navigation, Typing };
KeyRoute routeKey(int key, bool ctrl, Action action, bool typing, bool navigation, bool ring);
// The keys that act while a text field is typed into: Esc (the field undoes the typing and
// leaves, nothing else; a dialog's field: the dialog closes), the function keys (F1 help, F5
// present, F6 the next window, F11), PageDown and PageUp (the lesson) and Ctrl+Q; each but Esc
// leaves the field with what was typed.
bool keepsWhileTyping(int key, Action action);
// The key's name as the --verbose log writes it ("Shift+R", "Ctrl+S", "Right", "1", "F5"); "" for
// a key the table does not know (a modifier alone).
std::string keyName(int key, bool ctrl, bool shift);
// The action for `key` pressed with (or without) Ctrl and Shift, with thrust on or off;
// Action::None when unbound. A key bound without Shift also answers with Shift held when it has
// no Shift binding of its own. In the browser (`browser`), keys the browser keeps answer None.
Action actionForKey(int key, bool ctrl, bool shift = false, bool thrust = false,
                    bool browser = false);
// The unit vector a thrust action pushes along ((1, 0) for ThrustRight); zero for other actions.
Vec2 thrustDirectionOf(Action action);
// The direction the held thrust keys push (their bindings in the table, `isDown` asked for each
// key): the sum of their directions made unit length (Right and Up: diagonal, opposite keys
// cancel); zero when none is held.
Vec2 heldThrustDirection(const std::function<bool(int key)>& isDown);
// The digit a key types (0-9, top row or keypad); -1 for other keys.
int digitOfKey(int key);
// A short name for logs ("reset", "pause", ...).
const char* actionName(Action action);
// The key that does `action`, as Help names it ("P", "Space", "F5", "Ctrl+S"): its first binding
// in the table; "" when no key does it.
std::string keyNameOf(Action action);
// A button's or checkbox's label with the key that does the same: "Play (P)", "method (S)"; on a
// touch screen (`touch`: app.ui.touchUi) the label alone, "Play": a phone has no P. ImGui's id
// (after "###") is `text` either way, so the control stays the same control.
std::string keyedLabel(const std::string& text, Action action, bool touch);
// The action a panel control also does by key, by the control's name: an overlay's toggle by its
// --show name ("trails", "vectors": actionName's), the method's list ("method"); None otherwise.
Action actionOfControl(const std::string& name);
