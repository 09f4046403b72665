// The simulation session: the scene as loaded and the run stepped from it, the fixed-step clock,
// the timeline, what the plots and the inspector record, the cost measurement, and the one door
// for changes: every change to the world is an Edit applied by apply() (app/edit, docs/edits.md),
// which records the timeline's keyframe, marks the scene edited, prints the --verbose line and
// keeps it for undo. It knows nothing of the view, the lesson or the panels: the frame loop and
// the lesson session drive it (step, advance, reset, stopAtFrame, apply) and read what it did
// (FrameOutcome, notice). Plain logic: no GL, no ImGui; tested in tests/app.
#pragma once

#include "collision_announcer.h"
#include "collision_sound.h"
#include "cost.h"
#include "edit_history.h"
#include "edit_log.h"
#include "fixed_step.h"
#include "palette.h"
#include "poi.h"
#include "scene.h"
#include "side_by_side.h"
#include "telemetry.h"
#include "timeline.h"
#include "trails.h"
#include "world.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

// What one run owns: the world from a starting state and everything derived from stepping it.
// A load or reset starts a new one from the scene, a jump on the timeline from the recorded
// state (so its totals count from there: a replay does not count collisions twice).
struct Run {
    World world;
    StepStats stats;   // the last step's (momentum and energies of the start before any step)
    StepTotals totals; // since the run started
    Trails trails;
    PoiView poi;                          // point of impact of the watched block's last hit
    std::vector<CollisionRecord> lastLog; // collisions resolved in the last frame
    std::vector<Block> previousBlocks;    // the blocks at the start of the last frame
    MethodsSideBySide methods;            // the three methods from the same start
    Run() = default;
    explicit Run(World start);
};

// Thrust from the keyboard (the Physics section; lecture, "Spaceship thruster: normal engine, big
// ship: slow acceleration; small ship: fast acceleration"): with `on` and a dynamic block
// selected, the held arrow keys push that block with `force` newtons along `direction`, added to
// its own constant force for the frames they are held; released, no force. The thrust is never
// part of the world's state (not saved, not kept by the block). Kept by R and Shift+R (it is not
// in the scene file), set by a lesson step.
struct ThrustControl {
    bool on = false;
    double force = 10.0; // N (limits::kThrust)
    Vec2 direction;      // the held arrow keys' unit vector this frame; zero: none held
};

// What one frame of stepping did (the frame loop and the lesson session read it).
struct FrameOutcome {
    bool collided = false;    // a collision was resolved (rest-rule contacts not counted)
    bool reachedStop = false; // the frame reached stopAtFrame: the session paused there
    bool reachedEnd = false;  // the frame reached the scene's "duration": paused there
};

struct SimulationSession {
    // The scene as loaded (reset goes back to it) and where it came from.
    std::string scenePath;
    Scene scene;
    // The current run (a load or reset starts a new one; so does a jump on the timeline).
    Run run;
    std::vector<BlockLabel> labels;
    int selected = -1;
    // Run control. Scenes open paused at t = 0 (a collision at 0.625 s is over before anyone
    // looks); the scene view says "P to play".
    bool paused = true;
    bool slowMotion = false;
    double timeScale = 1.0;
    FixedStepClock clock;
    bool pauseOnCollision = false;
    bool pausedByCollision = false; // the last pause came from pauseOnCollision
    // Stepping pauses once, at the end of this frame (a lesson step's stop; reaching it clears
    // it). None: no such stop.
    std::optional<std::uint64_t> stopAtFrame;
    // Asked after every frame (the world, the frame's stats and its collisions): stepping pauses
    // at the end of a frame for which it says true. A lesson step's event, watched live
    // (lesson_runner.h, LessonWatch), whatever the lecturer changed. Empty: none.
    std::function<bool(const World&, const StepStats&, const std::vector<CollisionRecord>&)>
        stopWhen;
    // Stepping pauses once where the scene's "duration" ends (the scene has made its point); a
    // lesson turns this off, its steps stopping where they say.
    bool pauseAtSceneEnd = true;
    ThrustControl thrust;
    // The keys held for the scene's player this frame (scene.player; player.h): the arrow keys.
    // Never part of the world's state.
    PlayerKeys playerKeys;
    // A lesson step's scripted keys (its "input"): when not empty they play the player instead
    // of playerKeys, by the world's time, as sandbox-cli lesson plays them.
    std::vector<ScriptedKeys> script;
    // What the plots and the inspector read, and the timeline: recorded across runs started by a
    // jump on the timeline (the recording is cut at the jump when stepping resumes).
    Telemetry telemetry;
    WorldHistory history;
    CostMeasurement cost; // the cost overlay's measurement and tradeoff sweep
    // Each frame's collisions heard and told: the knocks (collision_sound.h; queued while the
    // sound is on, which by default it is in a lesson: `inLesson`, as the app last said) and the
    // screen reader's announcer (collision_announcer.h, the browser's page).
    SoundControl sound;
    bool inLesson = false;
    CollisionAnnouncer announcer;
    // The step's time is shown (the panel's Statistics open, as the app last drew it): the steps
    // are timed (WorldSettings::measureTime) while it is, or while the methods run side by side
    // (their overlay shows each one's time); else not (in the browser each clock read is a call
    // out to JavaScript).
    bool stepTimeShown = true;
    // Edits of blocks (drag, fling, add, delete, the panel's fields) since the last load or save;
    // quitting asks when there are any, or when the settings differ from the scene's.
    bool blocksEdited = false;
    // The edits applied (the undo and redo stacks, the journal since the last load or R).
    EditHistory edits;
    // Counts every change to the world through the door (an edit, undo or redo) and every
    // scene set: a reader that keeps the count sees the world changed since (the class poll
    // rewords its question).
    std::uint64_t changes = 0;
    // The last change through the door, as a screen reader says it ("bounciness C is now
    // 0.90", edit_words.h); "" after a scene is set.
    std::string lastChange;
    // An edit log playing (--edits; docs/edits.md): each line applies when the world reaches its
    // frame. R and Shift+R play it again from its start; loading another scene drops it.
    LogPlayer editLog;
    std::string editLogError; // the first refused line ("demo.jsonl:3: m2.mass: ..."); it stops
    bool verbose = false;     // --verbose: one stdout line per edit, undo and redo
    // What the session has to tell the user (an edit during a replay, the scene's end, no room
    // for a block): the app shows it as its note and clears it here.
    std::string notice;

    World& world() { return run.world; }
    const World& world() const { return run.world; }

    // Uses an already parsed scene: a new run, paused at t = 0, nothing selected, nothing edited.
    // `setup`: a lesson step's own setup (its "overrides", already in `scene`), printed for
    // --verbose as the edit prints, one line each ("setup: method: move-and-correct"); not an
    // edit of the run: nothing to undo, nothing in the journal.
    void setScene(const Scene& scene, const std::string& path, const std::vector<Edit>& setup = {});
    // R: the blocks and time back to the scene as loaded; the chosen method, bounciness, gravity,
    // frame rate and substeps stay (comparing methods is S then R). Trails cleared.
    void reset();
    // Shift+R, "reset to file": everything back to the scene as loaded, settings included.
    void resetToFile();
    // The one door: applies `edit` now (checked as applyEdit checks it) or refuses it (the
    // error says why; nothing changed). Applied, it is a keyframe of the timeline (while the
    // timeline replays a new future starts here, and the notice says so), a block edit marks
    // the scene edited, --verbose prints it and undo can take it back. `continues`: it goes on
    // the gesture begun by the last beginGesture() (a slider or a block dragged: one undo step).
    EditError apply(const Edit& edit, bool continues = false);
    // The next continuing edit starts a new gesture.
    void beginGesture() { edits.endGesture(); }
    // Ctrl+Z, Ctrl+Shift+Z / Ctrl+Y: the last edit undone or done again, at the world's present
    // frame; the notice says what ("undo: bounciness 0.90 -> 0.50", the panel's digits) or why
    // not. False when nothing was done.
    bool undo();
    bool redo();
    // What was done since the scene was loaded, a lesson step entered or the run restarted (R,
    // Shift+R), in order: every edit, undo and redo with its frame (the log Save edit log
    // writes; a lesson reads what the lecturer changed).
    const std::vector<JournalEntry>& editsSinceLoad() const { return edits.journal(); }
    // Plays the edit log's lines due at the world's frame (step() does after each frame; call it
    // after setting editLog). A refused line sets editLogError and the notice and stops the log.
    void playEditLog();
    // A restart that may change the world's settings without an edit (R, Shift+R, a lesson
    // step's restart): runs `restart`, then with --verbose prints each world key whose value it
    // changed, one line each as an edit's ("method: perfect"), in the panel's order (an edit
    // prints its own line where it is applied).
    void restartShowingChanges(const std::function<void()>& restart);
    // True when quitting would lose edits (see blocksEdited).
    bool unsavedEdits() const;

    // One simulation frame of settings.dt; updates stats, totals, trails and what is recorded,
    // and pauses where it should (a collision with pauseOnCollision, stopAtFrame, the scene's
    // end). `sideBySide`: the three methods run alongside (the overlay shows them).
    FrameOutcome step(bool sideBySide);
    // Advances the fixed-step clock by `realSeconds` and runs the due frames (none while
    // paused). Returns the number of frames run.
    int advance(double realSeconds, bool sideBySide);
    // Goes back (or forward) to frame `frame` of the timeline; false when it is not recorded.
    // Stepping from there replays, bit for bit, unless something is changed first. The
    // inspector's collisions become the last ones up to that frame (rebuilt from the history).
    bool scrubTo(std::uint64_t frame);
    // True while the world shows a frame earlier than the newest recorded one.
    bool isReplaying() const;

    // The block the keyboard thrust pushes this frame: the selected block when thrust is on, it
    // is dynamic and an arrow key is held; -1 otherwise.
    int thrustedBlock() const;
    // The thrust's force on it (N): direction · force; zero when thrustedBlock() is -1.
    Vec2 thrustForce() const;
    // The block the keys push this frame and their push (N), what the force arrow adds to the
    // block's own force: the thrust (thrustedBlock), else the scene's player while left or right
    // is held (its move force, player.h; a lesson's script holds them by the world's time); -1
    // and zero when the keys push nothing.
    int pushedBlock() const;
    Vec2 pushForce() const;
    // The force on block `index` this frame (N): its own constant force plus the keys' push on it.
    Vec2 appliedForce(int index) const;
    // perfect -> move-and-correct -> turn-based -> perfect (an edit of "method").
    void cycleMethod();
    // Edits of every world key (of a scene file) in which the world's settings differ from
    // `wanted`: the world then has those settings.
    void applySettings(const WorldSettings& wanted);

    // Edits of blocks, through apply(). Changes the kind of block `index` (dynamic blocks get
    // mass 1 kg when they had none).
    void setBlockKind(int index, BodyKind kind);
    // Resizes block `index` when the new size fits without overlap; false (nothing changed) if
    // not.
    bool setBlockSize(int index, Vec2 size);
    // Adds a 1 m dynamic block near `at` without overlap and selects it; returns its index or -1
    // (no room: the notice says so).
    int addBlockAt(Vec2 at);
    // Removes the selected block (if any).
    void deleteSelected();

    // The current state as a format v1 scene (names and colours kept).
    Scene currentScene() const;
    // `w` (a world of this session's blocks, such as a lesson's setup) as a scene, as above.
    Scene sceneOf(const World& w) const;
    // Saves currentScene() to `path` (absolute), which then is the current scene's file (what
    // the settings remember; reset to file goes back to it). False with `error` on failure.
    bool save(const std::string& path, std::string* error);

    // Name shown for block `index` ("#3" when it has none).
    std::string blockDisplayName(int index) const;
    // The colour block `index` is drawn in: its scene colour, else a palette colour (dynamic) or
    // the colour of static or kinematic blocks.
    Color blockDisplayColor(int index) const;

  private:
    void restartRun(); // a new run from the scene
    // After an edit, undo or redo: the timeline's keyframe, the edited mark, the selection
    // following added and removed blocks.
    void afterEdit(const AppliedEdit& applied, bool undone);
    // Undo (`back`) or redo: true when done; `error` says why a refused one was refused.
    bool undoOrRedo(bool back, EditError& error);
    // The one printer of what changed (--verbose): edits, undo and redo, a step's setup and the
    // settings a reset changed, each line printable (names come from files).
    void printChange(const std::string& line) const;
};

// True when the frame from frameStart to frameEnd (s) reaches the scene's "duration" (the app
// pauses there once; P plays on).
bool reachesSceneEnd(const Scene& scene, double frameStart, double frameEnd, double dt);