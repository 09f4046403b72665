// A student's trace opened on the current scene (issue 29; docs/compare.md): read, compared with
// the reference (app/compare), and what the app shows of it: the student's blocks at a frame
// (the ghost overlay's outlines), the first difference (the timeline's mark), the parting
// collision and the diagnosis (the inspector). Plain logic, no ImGui.
#pragma once

#include "compare.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

struct StudentTrace {
    std::string path;           // the file opened
    TraceUnitsSpec units;       // as the Compare section chose them
    std::optional<Trace> trace; // none: no trace open
    std::optional<TraceComparison> comparison;
    Scene scene; // the scene the trace was compared with

    bool open() const { return trace && comparison; }
    // The frame of the first difference; -1 when the trace is the reference's.
    std::int64_t firstDifference() const;
    // The trace's row for `frame`, or null (the trace has no such frame).
    const TraceRow* rowAt(std::int64_t frame) const;
    // `world` with the traced blocks where the trace has them at `frame` (the renderer draws it
    // as outlines); false when the trace has no row for that frame.
    bool ghostAt(std::int64_t frame, World& world) const;
};

// Reads `path` as a trace of `scene` under `settings` (the reference: the Tips' mistakes off)
// in `units`, and compares. On a bad file the trace stays as it was and the error (with its
// place) is returned.
std::optional<std::string> openStudentTrace(StudentTrace& st, const std::string& path,
                                            const Scene& scene, const WorldSettings& settings,
                                            const TraceUnitsSpec& units);
// A trace being opened a step at a time (the browser, one step a frame, so that its page answers
// keys meanwhile: issue 41): read at once, then compared one simulated run a step.
struct TraceOpening {
    std::string path;
    TraceUnitsSpec units;
    Scene scene;
    Trace trace;
    std::optional<TraceComparer> comparer; // reads scene and trace: the opening does not move
    // The app's count of changes (app.sim.changes) when the trace was read: the browser's
    // opening starts again on the world as it is when a scene was opened or an edit made since.
    std::uint64_t changesAtStart = 0;
};

// Reads `path` as openStudentTrace does and starts comparing; on a bad file, no opening and the
// error (with its place).
std::optional<std::string> startStudentTrace(std::unique_ptr<TraceOpening>& opening,
                                             const std::string& path, const Scene& scene,
                                             const WorldSettings& settings,
                                             const TraceUnitsSpec& units);
// One run of the comparison; true when it is over and `st` holds the trace.
bool continueStudentTrace(TraceOpening& opening, StudentTrace& st);

// One line for the panel: "different from frame 5 (t = 0.5 s): mover's x off by 1.25 m", or
// "the same as the reference over 100 frames".
std::string studentTraceSummary(const StudentTrace& st);
// True for a file the app opens as a trace rather than a scene (.csv, any case).
bool isTraceFile(const std::string& path);
