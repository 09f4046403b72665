// The edit log (docs/edits.md): JSON lines, one edit, undo or redo a line, each with the frame it
// applies at, e.g.
//   {"frame": 30, "set": "bounciness", "value": 0.5}
//   {"frame": 30, "set": "m2.mass", "value": 4}
//   {"frame": 60, "undo": true}
// read with errors that name file:line and the key, written from a session's journal
// (edit_history.h); and `--set KEY=VALUE`, the one-line form of an edit at frame 0. The
// programs replay a log with LogPlayer.
#pragma once

#include "edit_history.h"
#include "scene_error.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

// A log holds at most this many lines (blank ones aside), as a session's journal does.
inline constexpr std::size_t kMaxLogLines = kMaxJournal;

// One line of a log: what it does and where it was read, for messages ("demo.jsonl:3", or
// "lesson.json: steps[2].edits[0]" for a lesson step's edits).
struct LogLine {
    JournalEntry entry;
    std::string place;
};

struct EditLog {
    std::string source; // the file (or the name given), for messages
    std::vector<LogLine> lines;
};

struct EditLogResult {
    std::optional<EditLog> log;
    SceneError error; // when !log: "edits.jsonl:3: m2.mass: must be ..." or "edits.jsonl:3:14: ..."
};

// Reads log text (`source` names it in errors) or a file. Each line is checked as far as it can
// be without a world: its keys, its frame (a whole number within the frame budget, never before
// the line above), the key it sets (a world key of the table, or BLOCK.FIELD with a block field
// of the table); a value is checked when it is applied (applyEdit: the limits, the block named).
EditLogResult parseEditLog(const std::string& text, const std::string& source);
EditLogResult readEditLog(const std::string& path);
// The same lines as a JSON array of those objects (a lesson step's "edits", `path` its place:
// "lesson.json: steps[2].edits"); throws scene_json::ValueError naming the line and key
// ("steps[2].edits[0].frame").
EditLog editLogOf(const nlohmann::json& lines, const std::string& path);

// An edit applied from a log refused: "edits.jsonl:3: m2.mass: must be ...".
SceneError logLineError(const LogLine& line, const EditError& error);

// The edit a log's "set" names: a world key ("bounciness") or BLOCK.FIELD, the block by its
// name or its place ("m2.mass", "blocks[1].mass"; the field is after the last '.', so a name
// may hold dots and '='); refused with why.
std::optional<Edit> setEdit(const std::string& key, nlohmann::json value, EditError& error);
// `--set KEY=VALUE`: split after the first KEY that is a world key or ends in ".FIELD" (a name
// holding "=" and ".FIELD=" is written by its place), the value read as the row's kind reads
// text: a number, "X,Y" (or [X, Y]), a name, names separated by commas ("none": no name), a
// block's "static" or "kinematic", "none" for a block's own value back to the world's.
std::optional<Edit> parseSet(const std::string& text, EditError& error);

// One journal entry as a log line, and the log of a journal (its lines, in order).
std::string logLineText(const JournalEntry& entry);
std::string logText(const std::vector<JournalEntry>& journal);

// Plays a log's lines at their frames: next(frame) returns the next line due at `frame` (its
// frame at or before it) and moves past it, or null.
class LogPlayer {
  public:
    LogPlayer() = default;
    explicit LogPlayer(EditLog log) : log_(std::move(log)) {}
    const LogLine* next(std::uint64_t frame);
    const EditLog& log() const { return log_; }
    std::size_t remaining() const { return log_.lines.size() - at_; }
    bool empty() const { return log_.lines.empty(); }
    void restart() { at_ = 0; }

  private:
    EditLog log_;
    std::size_t at_ = 0;
};
