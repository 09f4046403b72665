// A lesson's step as parsed (docs/lesson-format.md): its scene with overrides, overlays, the event
// it pauses at, its question with choices and what the engine must reach there. The parsers of
// its parts (lesson_questions.h) and the lesson (lesson.h) read it; no GL, no ImGui.
#pragma once

#include "edit_log.h"
#include "lesson_text.h"
#include "scene.h"
#include "vocabulary.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

// What a step waits for (docs/lesson-format.md, "pause_at"): an event of the live run. The run
// pauses after the motion has gone on long enough to see its result (`watch`), or, when the
// event does not come within `within` seconds, there, saying so (no answer is claimed).
struct LessonPause {
    enum class Kind {
        None,
        Time,           // a time: the first frame ending at or after `time`
        Collision,      // the `collision`-th collision (walls included, rest-rule contacts not)
        BlockCollision, // `block`'s first collision (with anything: a block or a wall)
        PairCollision,  // the first collision of `block` with `other`
        Rest,           // `block` coming to rest (speed at most kRestSpeed)
        Reach,          // `block` reaching a place: its `side` at least `at` (or at most)
    };
    Kind kind = Kind::None;
    double time = 0.0;     // s (Time)
    int collision = 0;     // Collision: 1-based
    int block = -1;        // the block the event is about (index)
    int other = -1;        // PairCollision: the other block
    std::string blockName; // as written in the file
    std::string otherName;
    std::string side;    // Reach: "x", "y", "left", "right", "bottom" or "top"
    double at = 0.0;     // Reach: m
    bool atLeast = true; // Reach: side >= at (else <=)
    // s of watched motion after the event (at the step's time scale) before the pause; 0 for a
    // time (the time is the moment), and for an event whose own frame is the moment ("watch": 0:
    // the step pauses at the end of the event's frame, where its answer says the blocks are).
    double watch = 0.0;
    // s of simulated time the event may take; none: twice the step's moment as written (and,
    // for the step as written, the search of kCollisionSearchSeconds).
    std::optional<double> within;
};

// m/s: a block at most this fast has come to rest (LessonPause::Kind::Rest).
inline constexpr double kRestSpeed = 1e-6;
// s: the watched motion after an event, unless the step says (at least this much).
inline constexpr double kDefaultWatch = 1.0;

// One number the engine must reach at the pause point (or, in a step's `given`, that holds at its
// setup): equal within `tolerance`, or in [min, max].
struct LessonExpect {
    enum class Quantity {
        X,              // m, the block's centre
        Y,              // m
        Vx,             // m/s
        Vy,             // m/s
        Time,           // s, world time
        Collisions,     // collisions since the step began (as for LessonPause::Collision)
        MomentumX,      // kg·m/s, total over dynamic blocks
        MomentumY,      // kg·m/s
        KineticEnergy,  // J
        MaxPenetration, // m, the largest overlap met since the step began
        Left,           // m, the block's sides: x - width/2
        Right,          // m, x + width/2
        Bottom,         // m, y - height/2
        Top,            // m, y + height/2
        Mass,           // kg (infinite for static and kinematic blocks)
        FrameRate,      // frames/s, 1/dt
        Bounciness,     // C
    };
    std::string where; // "file: steps[3].expect[0]" (for messages)
    Quantity quantity = Quantity::X;
    int block = -1; // for X, Y, Vx, Vy
    std::string blockName;
    std::optional<double> equals;
    double tolerance = 1e-9; // absolute, with `equals`
    std::optional<double> min, max;
};

// The name of a quantity as the file writes it ("x", "vy", "kinetic_energy", ...).
const char* quantityName(LessonExpect::Quantity q);

// The blocks of all a lesson's scenes together (a scene shared by steps counts once): bounds the
// memory a lesson may take.
inline constexpr std::size_t kMaxLessonBlocks = 2000000;

// What a lesson file may refer to.
struct LessonContext {
    std::string scenesDir;                    // shipped scenes, for "scene": "bullet_wall"
    std::string baseDir;                      // scene paths are relative to it ("" = cwd)
    std::string lessonFile;                   // the lesson's own file: no step may name it
    std::size_t maxBlocks = kMaxLessonBlocks; // in all the lesson's scenes (lower in tests)
    std::vector<std::string> overlayNames;    // the overlay table's names; empty: not checked
};

// The work a step's run to its pause point may take, in block-steps (blocks x frames x
// substeps): bounds the time a lesson takes to validate (1e8: a few seconds).
inline constexpr double kMaxStepBlockSteps = 1e8;

// One prediction of a step's question (docs/lesson-format.md, "choices").
struct LessonChoice {
    LessonText text; // rendered at the setup, as the question is
    LessonExpr when; // "if": a condition at the moment (the event): this is what happened
    // What the answer says when the run proves this choice and not the correct one (the step's
    // answer explains the correct one); empty: the step's answer.
    LessonText answer;
};

// A question's choices: 2 to 4 (lettered A-D).
inline constexpr std::size_t kMinChoices = 2;
inline constexpr std::size_t kMaxChoices = 4;
// The letter of choice `index` (0-based): "A".."D".
inline std::string choiceLetter(std::size_t index) {
    return std::string(1, static_cast<char>('A' + index));
}

struct LessonStep {
    std::string title;
    std::string caption;     // one to three lines, separated by '\n' (a template: lesson_text.h)
    LessonText captionText;  // rendered at the setup, as the question is
    std::string place;       // "lesson.json: steps[3]", for the runner's messages
    std::string sceneSource; // the file the scene came from, or "" for an inline scene
    // With the step's overrides applied; shared by the steps that name one file with the same
    // overrides (parsed once: a lesson of 1000 steps on one 200,000-block scene holds it once).
    std::shared_ptr<const Scene> scene;
    // The step's "overrides" of world settings as edits ("frame_rate" the edit of dt), checked
    // when the lesson is read as any edit is (applyEdit: the settings table's limits) and
    // already in `scene`'s settings. They are the step, not a change to it: the app prints them
    // (--verbose, "setup: method: move-and-correct") and keeps them off the undo stack, so
    // Ctrl+Z never undoes a step's own setup (docs/lesson-format.md).
    std::vector<Edit> overrides;
    double timeScale = 1.0;            // simulated seconds per real second (the app's Time scale)
    std::vector<std::string> overlays; // names from the overlay table, on while the step shows
    int selected = -1;                 // block index, -1 for none
    // N: the keyboard thrust on with this force (the arrow keys push the selected block, which
    // is dynamic); none: thrust off.
    std::optional<double> thrust;
    // The scene's player's keys over time (lesson_input.h): the step plays itself. Empty: the
    // arrow keys.
    std::vector<ScriptedKeys> input;
    // Edits at their frames (docs/edits.md: the edit log's lines as a JSON array), applied by the
    // app and by the runner alike; those at frame 0 are part of the setup.
    EditLog edits;
    std::optional<Bounds> camera; // world rectangle to fit into the view; none: the bounds
    // The world rectangle fitted at the moment (the answer shown), so that the evidence the
    // question asks about is big enough (issue 39); none: `camera` stays.
    std::optional<Bounds> momentCamera;
    ViewFrame frame = ViewFrame::World; // "frame": "com": seen moving with the centre of mass
    LessonPause pause;
    // Named numbers of the step's texts and choices ("u": the centre of mass's velocity), each an
    // expression of the world that may read the ones before it.
    std::vector<std::string> valueNames;
    std::vector<LessonExpr> values;
    std::string question; // as written (a template: lesson_text.h), shown until the next press...
    LessonText questionText;
    // The predictions a class picks from (2 to 4, lettered A-D), each with the condition at the
    // moment under which it is what happened; `correct` is the one the step as written proves.
    std::vector<LessonChoice> choices;
    int correct = -1;
    // What the question says of the setup, checked there (t = 0, before any frame): a question
    // stays true of what the class sees when it is asked.
    std::vector<LessonExpect> given;
    std::string answer; // as written; ...which shows this and turns on `reveal`
    LessonText answerText;
    std::vector<std::string> reveal;
    std::vector<LessonExpect> expect;
};
