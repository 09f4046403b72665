// The app: its parts put together, each with one owner and a narrow interface (Dear ImGui's
// examples: the app owns its state, the UI binds widgets to it every frame, main owns the loop).
//   sim     the simulation session: the scene as loaded and its run, the clock, the timeline
//   lesson  the open lesson: it drives sim and view (never the other way round)
//   view    the camera, the frame of reference, the overlays shown, the layout
//   ui      what the panels keep between frames, the dialogs, the messages
//   mouse   what the mouse is doing in the scene
// The functions below are the glue: what one user action does to several parts. Plain logic
// with no GL or ImGui, tested on its own (tests/app).
#pragma once

#include "app_log.h"
#include "class_poll.h"
#include "classroom.h"
#include "csv_export.h"
#include "input_map.h"
#include "lesson_session.h"
#include "messages.h"
#include "mouse_tool.h"
#include "scene_library.h"
#include "simulation_session.h"
#include "student_trace.h"
#include "view.h"

#include <cstdint>
#include <string>
#include <vector>

// What the panels and overlay windows keep between frames (ImGui is immediate mode: the widgets
// keep nothing themselves), the dialogs, the messages, and the requests to the window backend.
// Plain data, no ImGui.
struct UiState {
    Messages messages;                // the panel's last error and note
    float plotSpanSeconds = 10.0f;    // s, the plots' time window
    int inspectorPicked = 0;          // the inspector's collision: 0 the newest, 1 the one before
    std::string inspectorLoggedTitle; // --verbose prints the formula once per collision shown
    int panelFollowedSelection = -2;  // the selection the "Selected block" header last followed
    int stepListFollowed = -1;        // the lesson step the panel's step list last scrolled to
    int stepListRows = 0;             // and how many rows it showed then
    TypedWarning typedWarning;        // a refused typed value, shown under its field
    // The docked window whose title bar the left button went down on (one at a time): dragging
    // on from there pulls it out of the layout.
    std::string titlePressed;
    // This frame, what the scene took on screen (px): the blocks, and the texts drawn over it
    // (axis numbers, labels, the arrows' values); the overlays' labels (point of impact, centre
    // of mass) avoid both, and a caption that must cover blocks hides no text if it can.
    struct TakenOnScreen {
        std::vector<ScreenRect> blocks, texts;
    } takenOnScreen;
    // This frame's axis numbers, placed (and taken) with the scene's texts but drawn after the
    // overlays: a caption plate over the scene may cover one (they yield to it), which is then
    // left out (scene_view.cpp's drawYieldedAxisNumbers); and the plates drawn (px).
    struct AxisNumber {
        ScreenRect rect;
        std::string text;
    };
    std::vector<AxisNumber> axisNumbers;
    std::vector<ScreenRect> captionPlates;
    std::string physicsFollowedScene; // the scene the "Physics" header last opened or closed for
    // The window the keyboard focus goes to this frame (Tab: the panel, F6: the next window);
    // "" when none. recordShownWindow moves ImGui's navigation there as the window is drawn.
    std::string keyboardFocus;
    // Who has the keyboard: "" the scene (every key is the key table's: the lecture's keys always
    // work and no focus ring shows; a slider dragged or a field clicked leaves it so), else the
    // window given it (F6, Tab; then a click in another window moves it there; ImGui's keyboard
    // navigation takes the arrows: input_map.h's routeKey) until Esc, a click in the scene or the
    // window going away gives it back (app_frame.cpp).
    std::string keyboardWindow;
    // The window a mouse button was pressed in this frame ("" none: the scene, or no press).
    std::string clickedWindow;
    bool helpOpen = false;
    bool firstLaunch = false; // no settings file yet: the start hint names the first keys
    // Dialogs: quit with unsaved edits, and Save (a name, and whether to overwrite).
    bool quitDialogOpen = false;
    bool saveDialogOpen = false;
    std::string saveDialogPath;
    std::string openPath;  // the Open field's path
    std::string tracePath; // the Compare section's path field
    std::string savedFile; // the file the last Save or export wrote (the browser downloads it)
    // The browser build: Open also offers the browser's file picker (and drag and drop), Save
    // downloads the file (named after the scene), there is no Quit (a tab is closed by the
    // browser) and the keys the browser keeps are its own (KeyBinding::inBrowser).
    bool inBrowser = false;
    bool filePickerRequested = false;
    bool copyLinkRequested = false; // "Copy link": the link for what is on screen (browser/link.h)
    bool touchUi = false;           // sizes for fingers (a touch screen; ui_style.h's uiFollowView)
    // Where the bounciness slider was last drawn (px; the window and browser tests press it).
    ScreenRect bouncinessSlider;
    // Requests to the window backend.
    bool quitRequested = false;
    bool fullscreenRequested = false;
    // The window's own pace (real time between displayed frames), for Statistics; zero offscreen.
    double frameMsSmoothed = 0.0; // ms, exponential average over about 30 frames
    long long framesShown = 0;
    double secondsShown = 0.0;
};

// The shipped scenes and lessons (the pickers) and where they are.
struct ShippedFiles {
    std::string scenesDir;
    std::vector<SceneEntry> scenes;
    std::string lessonsDir;
    std::vector<SceneEntry> lessons;
};

struct App {
    SimulationSession sim;
    LessonSession lesson;
    View view;
    UiState ui;
    MouseTool mouse;
    ShippedFiles shipped;
    // A student's trace opened on the scene (student_trace.h, docs/compare.md): the ghost
    // overlay's outlines, the timeline's mark, the inspector's "your trace". A new scene closes it.
    StudentTrace studentTrace;
    VerboseLog log;
    // The class poll (class_poll.h): on for the open lesson until turned off, the lesson closes
    // or the app quits (its server stops with it).
    ClassPoll poll;
};

// Loads `path` as the current scene (closing a lesson). On error, keeps the current scene, sets
// the error message and returns false.
bool loadScene(App& app, const std::string& path);
// Opens `path` as a student's trace of the current scene (units: app.studentTrace.units) and
// compares it with the reference (the current settings, the Tips' mistakes off): the run starts
// again from the scene, goes to the first difference and pauses there, with the ghost overlay,
// the timeline and the inspector shown. On error, keeps what was open, sets the error message
// and returns false.
bool openTrace(App& app, const std::string& path);
// What openTrace does once app.studentTrace holds the compared trace: the reference's settings
// from the scene's start, the ghost, timeline and inspector shown, the first difference, the
// note (the browser compares a frame at a time: browser/trace_opening.h).
void showOpenedTrace(App& app);
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
// R (outside a lesson): SimulationSession::reset, seen from the run's start.
void resetScene(App& app);
// Shift+R: SimulationSession::resetToFile, seen from the run's start.
void resetToFile(App& app);
// One frame of the simulation now (N, the step button), with the shown overlays' needs.
FrameOutcome stepSimulation(App& app);
// Advances the clock by `realSeconds` and runs the due frames (none while paused or while the
// mouse holds a block). Returns the number of frames run.
int advanceSimulation(App& app, double realSeconds);
// The timeline: SimulationSession::scrubTo, and the inspector shows the newest collision there.
bool scrubTo(App& app, std::uint64_t frame);
// Removes the selected block (if any); the mouse lets go.
void deleteSelected(App& app);
// Ctrl+Z (`undo`) or Ctrl+Y: SimulationSession::undo or redo; the mouse lets go, the note says
// what was undone.
void undoOrRedo(App& app, bool undo);
// Lays out the frame for a display of this size and points the camera (view.h's updateCamera,
// with the lesson's caption bar when a lesson is open).
void updateCamera(App& app, double displayWidth, double displayHeight);
// The session's notice, if any, becomes the panel's note.
void takeNotice(App& app);
// The window showed a frame `realSeconds` after the previous one (its pace, for Statistics).
void noteFrameShown(UiState& ui, double realSeconds);

// Ctrl+Q or the window's close button: quits, or opens the quit dialog when there are unsaved
// edits (a second request while it is open quits).
void requestQuit(App& app);
// Esc (see escapeEffect): returns what it did. `keyboardBack`: it also gives the keyboard back to
// the scene (app_frame.cpp), so that doing nothing else needs no note.
EscapeEffect pressEscape(App& app, bool keyboardBack = false);

// Saves the current state to `path` (made absolute), which then is the current scene's file;
// sets the note or the error.
bool saveCurrentScene(App& app, const std::string& path);
// Where Save offers to write (and the plots' CSV exports go): the scene's own directory unless
// that is the shipped scenes' (then the working directory).
std::string saveDirectory(const App& app);
// The path the Save dialog offers: from the scene's name, in saveDirectory(), never an existing
// file.
std::string suggestedSavePath(const App& app);
// Where Save writes in the browser build, which then offers the file as a download of that name:
// kBrowserDownloads/STEM.json, STEM from the scene's name ("bouncing_squares.json").
inline constexpr const char* kBrowserDownloads = "/downloads";
std::string browserDownloadPath(const App& app);

// Writes the session's journal (editsSinceLoad) as an edit log (docs/edits.md) in
// saveDirectory(), named after the scene (lecture_example_1-edits.jsonl, then -2, ...: never an
// existing file); the note names the file and the browser offers it as a download. Returns the
// path, or "".
std::string saveEditLog(App& app);
// Writes a plot's table (csv_export.h) in saveDirectory(), named after the scene and the plot
// (lecture_example_1-momentum.csv, then -2, ...: never an existing file); the note
// names the file ("Wrote 120 rows to /path/x-momentum.csv") and the browser offers it as a
// download (ui.savedFile), or the error says why not. Returns the path, or "".
std::string exportCsv(App& app, const std::string& plot, const CsvTable& table);

// The lesson (lesson_session.h) driving this app's simulation and view, reporting in its
// messages; the mouse lets go and a refused typed value is forgotten when a step is entered.
bool openLesson(App& app, const std::string& path, std::size_t first = 0);
void closeLesson(App& app);
bool enterStep(App& app, std::size_t index);
// The lesson's keys (input_map.h): LessonNext (PageDown, Right: the answer, then the next step),
// LessonPrevious, LessonFirst, LessonLast, LessonJump (the digits typed, then Enter), and Reset,
// which restarts the step. True when it handled the action (false: not a lesson action, or no
// lesson open and the action is Reset).
bool applyLessonAction(App& app, Action action);
void lessonShowPausePoint(App& app);
