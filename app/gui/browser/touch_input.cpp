#include "touch_input.h"

#include <cmath>

namespace {

double distance(Vec2 a, Vec2 b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

} // namespace

void TouchInput::event(TouchPhase phase, int id, Vec2 pos, double time) {
    active_ = true;
    if (phase == TouchPhase::Start) {
        fingers_[id] = pos;
        if (fingers_.size() >= 2) { // a second finger: the gesture; a press in progress ends
            if (mode_ == Mode::Scene || mode_ == Mode::Held) {
                releaseFrame_ = true;
                releaseAt_ = now_;
            }
            mode_ = Mode::Two;
            return;
        }
        mode_ = Mode::Waiting;
        waitedFrame_ = false;
        liftedWaiting_ = false;
        finger_ = id;
        start_ = now_ = last_ = pos;
        startTime_ = time;
        return;
    }
    if (fingers_.find(id) == fingers_.end()) return; // a finger this never saw go down
    if (phase == TouchPhase::Move) fingers_[id] = pos;
    const bool lifted = phase == TouchPhase::End || phase == TouchPhase::Cancel;
    if (lifted) fingers_.erase(id);
    if (mode_ == Mode::Two) {
        if (fingers_.empty()) mode_ = Mode::None;
        return;
    }
    if (id != finger_) return;
    now_ = pos;
    const bool held = time - startTime_ >= config_.holdSeconds;
    if (!lifted) {
        if (mode_ == Mode::Pending && held) {
            mode_ = Mode::Held; // still for the hold time: this move drags
        } else if (mode_ == Mode::Pending && distance(pos, start_) > config_.slopPx) {
            mode_ = Mode::Scroll;
            last_ = start_; // the content follows the finger from where it went down
        }
        return;
    }
    switch (mode_) {
    case Mode::Waiting:
        if (phase == TouchPhase::End)
            liftedWaiting_ = true; // a tap, once it is known where
        else
            mode_ = Mode::None;
        return;
    case Mode::Pending:
        if (phase == TouchPhase::End) {
            tapFrames_ = 2;
            tapAt_ = start_;
            tapCtrl_ = true;
        }
        break;
    case Mode::Held:
    case Mode::Scene:
        releaseFrame_ = true;
        releaseAt_ = pos;
        break;
    case Mode::Scroll:
    case Mode::Pan:
        tail_ = pos - last_;
        tailIsPan_ = mode_ == Mode::Pan;
        break;
    default:
        break;
    }
    mode_ = Mode::None;
}

void TouchInput::resolveStart(bool overUi, bool onBlock) {
    if (!waitingForStart()) return;
    const bool moved = distance(now_, start_) > config_.slopPx;
    if (liftedWaiting_) { // it came and went before a frame showed where
        liftedWaiting_ = false;
        mode_ = Mode::None;
        if (moved && (overUi || !onBlock)) { // a swipe or a pan, all of it at once
            tail_ = now_ - start_;
            tailIsPan_ = !overUi;
            return;
        }
        tapFrames_ = 2; // a tap: on the UI as Ctrl+click, on the scene a plain one
        tapAt_ = start_;
        tapCtrl_ = overUi;
        return;
    }
    onBlock_ = onBlock;
    if (overUi) {
        mode_ = moved ? Mode::Scroll : Mode::Pending;
        last_ = start_;
    } else if (moved && !onBlock) {
        mode_ = Mode::Pan;
        last_ = start_;
    } else {
        mode_ = Mode::Scene;
        sceneFirst_ = true;
    }
}

TouchInput::Frame TouchInput::frame(double now) {
    Frame f;
    if (tapFrames_ > 0) { // down, then up, where the tap was
        f.pointer = true;
        f.pos = tapAt_;
        f.down = tapFrames_ == 2;
        f.ctrl = tapCtrl_;
        --tapFrames_;
        return f;
    }
    if (tail_.x != 0.0 || tail_.y != 0.0) { // the rest of a swipe or pan
        if (tailIsPan_)
            f.pan = tail_;
        else
            f.scrollY = tail_.y;
        tail_ = Vec2{};
    }
    if (releaseFrame_) {
        releaseFrame_ = false;
        f.pointer = true;
        f.pos = releaseAt_;
        return f;
    }
    switch (mode_) {
    case Mode::None:
    case Mode::Two:
        break;
    case Mode::Waiting:
        f.pointer = true; // hovering where the finger went down: the next frame tells what is there
        f.pos = start_;
        waitedFrame_ = true;
        break;
    case Mode::Pending:
        f.pointer = true; // hovered: a tooltip shows while the finger rests, not after
        f.pos = start_;
        f.startedOnUi = true;
        if (now - startTime_ >= config_.holdSeconds) {
            mode_ = Mode::Held;
            f.pos = now_;
            f.down = true;
        }
        break;
    case Mode::Scroll:
        f.scrollY = now_.y - last_.y; // the pointer is off: nothing under the finger hovers
        f.startedOnUi = true;
        last_ = now_;
        break;
    case Mode::Held:
        f.pointer = true;
        f.pos = now_;
        f.down = true;
        f.startedOnUi = true;
        break;
    case Mode::Scene:
        f.pointer = true;
        f.pos = sceneFirst_ ? start_ : now_;
        f.down = true;
        sceneFirst_ = false;
        if (!onBlock_ && distance(now_, start_) > config_.slopPx) { // from empty space: a pan
            mode_ = Mode::Pan;
            f.pos = now_;
            f.down = false;
            last_ = start_;
        }
        break;
    case Mode::Pan:
        f.pan = now_ - last_;
        last_ = now_;
        break;
    }
    return f;
}
