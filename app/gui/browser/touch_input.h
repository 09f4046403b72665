// What fingers on a phone or tablet do, decided as they move (pure logic; the browser canvas
// feeds it the page's touch events and applies what it says to ImGui and the scene every frame).
// One finger:
//   on the panel or a window  a tap clicks, as Ctrl+click, so a number field (a slider, a drag
//                             field) opens for typing with the on-screen keyboard; a swipe
//                             scrolls what is under it and presses nothing (a slider under it
//                             keeps its value); held still for kHoldSeconds, then moved, it
//                             presses and drags (a slider's grab, a window's title)
//   on the scene              the mouse's left button at once: a tap selects (two quick taps add
//                             a block, as a double-click), a drag from a block moves it; a drag
//                             from empty space pans the view
// Two fingers pan and zoom (TouchGesture, canvas_web.h). After a touch ends the pointer leaves
// the screen, so nothing stays hovered (no tooltip stuck after a tap).
#pragma once

#include "vec2.h"

#include <map>

enum class TouchPhase { Start = 0, Move = 1, End = 2, Cancel = 3 };

// Distances are framebuffer pixels; `slopPx` is how far a finger may wander and still tap.
struct TouchConfig {
    double slopPx = 10.0;
    double holdSeconds = 0.35;
};

class TouchInput {
  public:
    enum class Mode {
        None,    // no finger (the pointer is off the screen once a tap is delivered)
        Waiting, // one finger down, where it is not known yet (the next frame tells)
        Pending, // on the UI: a tap, a swipe or a hold, still undecided
        Scroll,  // on the UI: a swipe
        Held,    // on the UI: held, then pressing (the mouse button down)
        Scene,   // on the scene: the mouse button down from the start
        Pan,     // on the scene, from empty space: the view follows the finger
        Two,     // two fingers (the canvas's gesture)
    };

    // What ImGui's mouse is this frame, and what to scroll or pan.
    struct Frame {
        bool pointer = false; // false: off the screen (the mouse position ImGui calls none)
        Vec2 pos;
        bool down = false;
        bool ctrl = false;    // a tap on the UI: Ctrl+click
        double scrollY = 0.0; // px the UI under the swipe moves (its content follows the finger)
        Vec2 pan;             // px the scene's view moves
        bool startedOnUi = false;
    };

    explicit TouchInput(TouchConfig config = {}) : config_(config) {}

    // A touch event (`id` the finger, `pos` in framebuffer pixels, `time` in seconds).
    void event(TouchPhase phase, int id, Vec2 pos, double time);
    // Once per frame, before the UI's frame: what the mouse is this frame (`now` in seconds).
    Frame frame(double now);
    // After a frame that had the pointer at a new finger (waitingForStart()): whether the UI is
    // under it, and on the scene whether a block is.
    void resolveStart(bool overUi, bool onBlock);
    // A real mouse moved: touch gives the pointer back.
    void mouseMoved() { active_ = false; }
    // True while touch owns the pointer (since the last touch, until a mouse moves).
    bool active() const { return active_; }
    Mode mode() const { return mode_; }
    // How many fingers are down.
    std::size_t fingers() const { return fingers_.size(); }
    // True when the last frame asked for resolveStart().
    bool waitingForStart() const { return mode_ == Mode::Waiting && waitedFrame_; }

  private:
    TouchConfig config_;
    std::map<int, Vec2> fingers_;
    Mode mode_ = Mode::None;
    bool active_ = false;
    bool waitedFrame_ = false; // Waiting: a frame showed the pointer at the finger
    int finger_ = -1;          // the one finger of a one-finger mode
    Vec2 start_, now_, last_;  // that finger: where it went down, is, was at the last frame
    double startTime_ = 0.0;
    bool onBlock_ = false;
    bool liftedWaiting_ = false; // it lifted before the frame that tells where it was
    bool sceneFirst_ = false;    // Scene: the first frame presses where the finger went down
    // A tap on the UI is delivered over two frames (down, then up) after the finger lifted.
    int tapFrames_ = 0;
    Vec2 tapAt_;
    bool tapCtrl_ = false;
    bool releaseFrame_ = false; // the button goes up this frame (a press or scene drag ended)
    Vec2 releaseAt_;
    Vec2 tail_; // a swipe's or pan's last move, when the finger lifted before a frame showed it
    bool tailIsPan_ = false;
};
