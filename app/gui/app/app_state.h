// The application's state: the loaded scene, the world, selection, camera and toggles. The UI
// (ImGui, immediate mode) binds its widgets to this struct every frame; everything here is plain
// logic with no GL or ImGui, so it is tested on its own.
#pragma once

#include "app_log.h"
#include "camera.h"
#include "classroom.h"
#include "collision_sound.h"
#include "cost.h"
#include "dock_layout.h"
#include "fixed_step.h"
#include "lesson_session.h"
#include "mouse_tool.h"
#include "options.h"
#include "palette.h"
#include "poi.h"
#include "scene.h"
#include "scene_library.h"
#include "side_by_side.h"
#include "spoken_text.h"
#include "student_trace.h"
#include "telemetry.h"
#include "timeline.h"
#include "trails.h"
#include "view_frame.h"
#include "world.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

// What each block is called and how it is coloured; parallel to world.blocks (the engine's Block
// has no name), kept in step when blocks are added or removed.
struct BlockLabel {
    std::string name;
    std::string color; // "#rrggbb" or "" for the palette
};

// Velocity arrows are on by default for scenes with at most this many blocks (more is clutter).
constexpr std::size_t kVectorsByDefaultUpTo = 50;

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

// What the panels and overlay windows keep between frames (ImGui is immediate mode: the widgets
// keep nothing themselves). Plain data, no ImGui.
struct UiState {
    float plotSpanSeconds = 10.0f;    // s, the plots' time window
    int inspectorPicked = 0;          // the inspector's collision: 0 the newest, 1 the one before
    std::string inspectorLoggedTitle; // --verbose prints the formula once per collision shown
    int panelFollowedSelection = -2;  // the selection the "Selected block" header last followed
    TypedWarning typedWarning;        // a refused typed value, shown under its field
    // The docked window whose title bar the left button went down on (one at a time): dragging
    // on from there pulls it out of the layout.
    std::string titlePressed;
    // This frame, what the scene's labels took on screen (px): the blocks, their labels, the
    // arrows' values; the overlays' labels (point of impact, centre of mass) avoid them.
    std::vector<ScreenRect> takenOnScreen;
    std::string physicsFollowedScene; // the scene the "Physics" header last opened or closed for
    // The window the keyboard focus goes to this frame (Tab: the panel, F6: the next window);
    // "" when none. recordShownWindow moves ImGui's navigation there as the window is drawn.
    std::string keyboardFocus;
};

// The app: the current Run (its base, so app.world is the run's world; restart and scrub assign
// it whole: app.run() = Run(world)), plus what outlives a run.
struct App : Run {
    Run& run() { return *this; }
    const Run& run() const { return *this; }
    // The scene as loaded (Reset goes back to it) and where it came from.
    std::string scenePath;
    Scene scene;
    // The live state (the world is the Run's).
    std::vector<BlockLabel> labels;
    int selected = -1;
    // Run control. Scenes open paused at t = 0 (a collision at 0.625 s is over before anyone
    // looks); the scene view says "P to play".
    bool paused = true;
    bool slowMotion = false;
    double timeScale = 1.0;
    FixedStepClock clock;
    // View.
    Camera camera;
    bool autoFit = true; // refit the camera when the viewport changes, until the user zooms/pans
    std::optional<Bounds> fitBounds; // what fitting shows (a lesson step's camera); none: bounds
    // The frame of reference (view_frame.h): in the centre of mass's the camera moves with u and
    // the arrows show w = v - u (View section, U, --frame com, a lesson step's "frame").
    ViewFrame frame = ViewFrame::World;
    FrameCamera frameCamera;
    Overlays show;
    bool overlaysChosen = false; // --show given: scenes no longer pick the default overlays
    bool uiVisible = true;
    bool helpOpen = false;
    float uiScale = 1.0f;
    // Present mode (F5): the scene and a one-line caption only; every panel and window hidden,
    // and back as they were when it is left.
    bool presentMode = false;
    bool fullscreen = false;  // the window is full screen (the window backend keeps it true)
    bool firstLaunch = false; // no settings file yet: the start hint names the first keys
    bool lightTheme = false;  // View section; persisted
    float labelScale = 1.0f;  // size of the scene's labels relative to the UI font; persisted
    // This frame's layout: the panel, the docked overlay windows and the scene's rectangle.
    Layout layout;
    // Overlay windows pulled out of the layout to float (by title); put back with "Dock".
    std::vector<std::string> floatingWindows;
    // Every window drawn this frame with its rectangle (for --layout-json), in drawing order.
    std::vector<DockedWindow> shownWindows;
    // Edits of blocks (drag, fling, add, delete, the panel's fields) since the last load or save;
    // quitting asks when there are any, or when the settings differ from the scene's.
    bool blocksEdited = false;
    // Dialogs: quit with unsaved edits, and Save (a name, and whether to overwrite).
    bool quitDialogOpen = false;
    bool saveDialogOpen = false;
    std::string saveDialogPath;
    MouseTool mouse;
    // The window's own pace (real time between displayed frames), for Statistics; zero offscreen.
    double frameMsSmoothed = 0.0; // ms, exponential average over about 30 frames
    long long framesShown = 0;
    double secondsShown = 0.0;
    // What the plots and the inspector read, and the timeline: recorded across runs started by a
    // jump on the timeline (the recording is cut at the jump when stepping resumes).
    Telemetry telemetry;
    WorldHistory history;
    CostMeasurement cost; // the cost overlay's measurement and tradeoff sweep
    UiState ui;
    ThrustControl thrust;
    SoundControl sound;           // the collisions' knocks (M; View section)
    CollisionAnnouncer announcer; // the collisions for a screen reader (the browser's page)
    bool pauseOnCollision = false;
    bool pausedByCollision = false; // the last pause came from pauseOnCollision
    // Messages for the panel: the last error (load or save) and the last note.
    std::string error;
    std::string note;
    // Requests to the window backend.
    bool quitRequested = false;
    bool fullscreenRequested = false;
    std::string savePath;  // the Save field's path
    std::string openPath;  // the Open field's path
    std::string savedFile; // the file the last Save wrote (the browser offers it as a download)
    // The browser build: Open also offers the browser's file picker (and drag and drop), Save
    // downloads the file.
    bool browserFiles = false;
    bool filePickerRequested = false;
    // The shipped scenes (the picker) and where they are.
    std::string scenesDir;
    std::vector<SceneEntry> sceneFiles;
    // A student's trace opened on the scene (student_trace.h, docs/compare.md): the ghost
    // overlay's outlines, the timeline's mark, the inspector's "your trace"; the Compare
    // section's path field. A new scene closes it.
    StudentTrace studentTrace;
    std::string tracePath;
    // The open lesson (lesson_session.h), the shipped lessons (the picker) and where they are.
    LessonSession lesson;
    std::string lessonsDir;
    std::vector<SceneEntry> lessonFiles;
    double captionHeight = 0.0; // px the lesson's caption bar takes at the top of the scene
    // --verbose: print state changes to stdout.
    bool verbose = false;
    LoggedState logged;
    bool loggedValid = false;
    bool layoutLogged = false; // --verbose prints one slider's place once (for the window test)
};

// Width of the controls panel in pixels for a UI scale and window width.
double panelWidth(float uiScale, double displayWidth);
// Pixels (at UI scale 1) between the world's bounds and the scene's rectangle when the camera
// fits the world: room for the axis numbers and, at the top, the status badge or caption.
constexpr double kFitMarginPx = 36.0;
// This frame's layout: the panel (unless hidden), the shown overlay windows that are not floating
// docked around the scene (none in present mode), and the scene's rectangle.
Layout computeAppLayout(const App& app, double displayWidth, double displayHeight);
// The part of the window the scene is drawn into (computeAppLayout's scene).
ScreenRect sceneViewport(const App& app, double displayWidth, double displayHeight);
// Lays out the frame (app.layout), gives the camera the scene's rectangle and refits the world
// while app.autoFit holds.
void updateCamera(App& app, double displayWidth, double displayHeight);
// Sees the scene in `frame` from now on (the camera follows the centre of mass from where it is).
void setViewFrame(App& app, ViewFrame frame);
// Changes the kind of block `index` (dynamic blocks get mass 1 kg when they had none).
void setBlockKind(App& app, int index, BodyKind kind);
// Resizes block `index` when the new size fits without overlap; false (nothing changed) if not.
bool setBlockSize(App& app, int index, Vec2 size);

// Loads `path` as the current scene (closing a lesson). On error, keeps the current scene, sets
// app.error and returns false.
bool loadScene(App& app, const std::string& path);
// Opens `path` as a student's trace of the current scene (units: app.studentTrace.units) and
// compares it with the reference (the current settings, the Tips' mistakes off): the run starts
// again from the scene, goes to the first difference and pauses there, with the ghost overlay,
// the timeline and the inspector shown. On error, keeps what was open, sets app.error and
// returns false.
bool openTrace(App& app, const std::string& path);
// Compares the open trace again with the current settings (after the method was changed).
bool compareTraceAgain(App& app);
// Goes to the open trace's first difference (the timeline's frame, or the run started again and
// stepped there) and pauses; false when there is none.
bool goToFirstDifference(App& app);
void closeTrace(App& app);
// A dropped or picked file: a trace (.csv) or a scene.
bool openFile(App& app, const std::string& path);
// Uses an already parsed scene (tests, and the first scene when none can be loaded).
void setScene(App& app, const Scene& scene, const std::string& path);
// R: the blocks and time back to the scene as loaded; the chosen method, bounciness, gravity,
// frame rate and substeps stay (comparing methods is S then R). Trails cleared.
void resetScene(App& app);
// Shift+R, "reset to file": everything back to the scene as loaded, settings included.
void resetToFile(App& app);
// The user changed the world (`blocks`: a block; otherwise a setting) between steps. While the
// timeline replays, this starts a new future from here, and the note says so.
void noteEdit(App& app, bool blocks);
// True when quitting would lose edits (see App::blocksEdited).
bool unsavedEdits(const App& app);
// Ctrl+Q or the window's close button: quits, or opens the quit dialog when there are unsaved
// edits (a second request while it is open quits).
void requestQuit(App& app);
// Present mode on or off: every panel and window hidden, and back as they were.
void setPresentMode(App& app, bool on);
// Esc (see escapeEffect): returns what it did.
EscapeEffect pressEscape(App& app);
// One simulation frame of settings.dt; updates stats, totals and trails.
void stepSimulation(App& app);
// Advances the fixed-step clock by `realSeconds` and runs the due frames (none while paused or
// while the mouse holds a block). Returns the number of frames run.
int advanceSimulation(App& app, double realSeconds);
// The window showed a frame `realSeconds` after the previous one (its pace, for Statistics).
void noteFrameShown(App& app, double realSeconds);
// Goes back (or forward) to frame `frame` of the timeline; false when it is not recorded.
// Stepping from there replays, bit for bit, unless something is changed first. The inspector's
// collisions become the last ones up to that frame (rebuilt from the history).
bool scrubTo(App& app, std::uint64_t frame);
// True while the world shows a frame earlier than the newest recorded one.
// True when the frame from frameStart to frameEnd (s) reaches the scene's "duration" (the app
// pauses there once; P plays on).
bool reachesSceneEnd(const Scene& scene, double frameStart, double frameEnd, double dt);
bool isReplaying(const App& app);
// The block the keyboard thrust pushes this frame: the selected block when thrust is on, it is
// dynamic and an arrow key is held; -1 otherwise.
int thrustedBlock(const App& app);
// The thrust's force on it (N): direction · force; zero when thrustedBlock() is -1.
Vec2 thrustForce(const App& app);
// The force on block `index` this frame (N): its own constant force plus the thrust on it.
Vec2 appliedForce(const App& app, int index);
// True when the scene uses what the Physics section sets (a resolve, integrator, mistake or drag
// other than the default, a block's force) or the thrust is on: the section opens for it.
bool usesPhysicsSection(const App& app);
// perfect -> move-and-correct -> turn-based -> perfect.
void cycleMethod(App& app);
// The current state as a format v1 scene (names and colours kept).
Scene currentScene(const App& app);
// Saves currentScene() to `path` (made absolute), which then is the current scene's file (what
// the settings remember; reset to file goes back to it); sets app.note or app.error.
bool saveCurrentScene(App& app, const std::string& path);
// The path the Save dialog offers: from the scene's name, in the scene's own directory unless
// that is the shipped scenes' (then the working directory), never an existing file.
std::string suggestedSavePath(const App& app);
// Where Save offers to write (and the plots' CSV exports go): the scene's own directory unless
// that is the shipped scenes' (then the working directory).
std::string saveDirectory(const App& app);
// True when `path` names something on disk (an error reads as false).
bool pathExists(const std::string& path);
// Is `title` an overlay window pulled out of the layout to float?
bool isFloating(const App& app, const std::string& title);
void setFloating(App& app, const std::string& title, bool floating);
// Adds a 1 m dynamic block near `at` without overlap; returns its index or -1 (no room).
int addBlockAt(App& app, Vec2 at);
// Removes the selected block (if any).
void deleteSelected(App& app);
// Sets the overlays from a --show list.
void applyShowSet(App& app, const ShowSet& show);
// Clamps the UI scale into its range.
void setUiScale(App& app, float scale);
// The colour block `index` is drawn in: its scene colour, else a palette colour (dynamic) or the
// colour of static or kinematic blocks.
Color blockDisplayColor(const App& app, int index);
// Name shown for block `index` ("#3" when it has none).
std::string blockDisplayName(const App& app, int index);
