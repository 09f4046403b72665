// The sandbox-cli subcommands as plain functions: main.cpp only parses the command line.
#pragma once

#include "lesson.h"
#include "settings_table.h"

#include <csignal>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

// Exit codes of sandbox-cli.
// kExitInterrupted: `run` stopped by SIGINT (128 + 2, what shells report), after its summary.
enum ExitCode : int { kExitOk = 0, kExitBadInput = 1, kExitUsage = 2, kExitInterrupted = 130 };

// Progress of a long run on stderr (one report a second after the first second): off, a line
// rewritten in place (stderr is a terminal), or one line per report (--progress).
enum class ProgressLines { Off, Terminal, Lines };

// A world setting's flag and the text it was given.
struct SettingFlag {
    const settings_table::WorldKey* row;
    std::string text;
};

// `run`, as typed on the command line: option values stay text until runCommand checks them, so
// a bad value is reported as bad input (exit 1), not as bad usage.
struct RunRequest {
    std::string scene; // path of the scene file
    // The world settings' flags as given (--method, --dt, --gravity, ...; settings_table.h), in
    // sandbox-cli's order (settings_table::cliOrder); a repeatable flag (--mistake) once per use.
    std::vector<SettingFlag> settings;
    std::optional<std::string> steps; // frames to simulate, >= 0
    std::optional<std::string> time;  // s of simulated time to reach, >= 0
    std::optional<std::string> trace; // CSV file: a header and one row per frame
    // Edits (docs/edits.md): --set KEY=VALUE at frame 0 (after the flags above), in the order
    // given, then the lines of the --edits log at their frames.
    std::vector<std::string> sets;
    std::optional<std::string> edits;
    bool json = false; // print one JSON object instead of a summary
    ProgressLines progress = ProgressLines::Off;
    // Set (by a SIGINT handler) to stop the run after the current frame; the summary of the
    // frames done is printed and runCommand returns kExitInterrupted. Null: never stops early.
    const volatile std::sig_atomic_t* interrupted = nullptr;
};

// Default length of a run when neither --steps nor --time is given.
constexpr std::int64_t kDefaultSteps = 600;

// Simulates the scene and prints the summary to `out`; errors go to `err`. Returns an ExitCode.
int runCommand(const RunRequest& request, std::ostream& out, std::ostream& err);
// Prints "ok" to `out`, or the error (naming its place) to `err`. Returns an ExitCode. A file with
// a "steps" key is a lesson (docs/lesson-format.md), anything else a scene.
int validateCommand(const std::string& path, std::ostream& out, std::ostream& err,
                    const LessonContext& lessons = {});
// Runs every step of a lesson to its pause point and prints, per step, where it paused and each
// block's position and velocity there, then every failed expectation (exit 1 if any). With
// `json`: one JSON object, each step's pause time, frame, collisions, contacts, time scale and
// seconds of motion (pause time / time scale), its blocks there and its failures.
int lessonCommand(const std::string& path, std::ostream& out, std::ostream& err,
                  const LessonContext& lessons = {}, bool json = false);
