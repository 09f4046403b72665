// The undo and redo stacks over edits (edit.h), and the journal of what was done: every edit,
// undo and redo with the frame it came at, which is the edit log a session saves
// (edit_log.h writes it, docs/edits.md) and what a lesson reads of the lecturer's changes.
// sandbox-cli run replays a log's undo and redo through it; the GUI's session wraps it with the
// timeline, the edited mark and the --verbose log.
#pragma once

#include "edit.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

// How far back undo reaches, and how many lines the journal keeps (a longer session's journal
// stops there: journalFull(), and the log it saves says so).
inline constexpr std::size_t kMaxUndo = 10000;
inline constexpr std::size_t kMaxJournal = 100000;

// One line of the journal, as the edit log writes it.
struct JournalEntry {
    enum class What : std::uint8_t { Edit, Undo, Redo };
    What what = What::Edit;
    std::uint64_t frame = 0; // the world's frame when it was done (before that frame's step)
    Edit edit;               // What::Edit: as asked (a block by its name when one block has it)
    // One undo step with the edit before it (a slider or a block dragged while frames ran).
    bool continues = false;
};

// What an undo or redo did: the edit it undid or did again (as applied: before and after), or
// why nothing was done.
struct UndoResult {
    const AppliedEdit* edit = nullptr; // null: nothing to undo (or redo), or refused
    EditError error;
};

class EditHistory {
  public:
    // Applies `edit` at `frame`; when it is applied, it goes on the undo stack (joined with the
    // last one when `continues` and it is of the same key and block: one gesture, one undo
    // step), the redo stack is emptied, and the journal records it.
    ApplyResult apply(EditTarget target, const Edit& edit, std::uint64_t frame,
                      bool continues = false);
    // The last edit undone (redo: the last undone done again), journaled at `frame`.
    UndoResult undo(EditTarget target, std::uint64_t frame);
    UndoResult redo(EditTarget target, std::uint64_t frame);
    // The next continuing edit begins a new undo step (a new gesture).
    void endGesture() { joinable_ = false; }
    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    // The edit the next undo (redo) would undo (do again); null when none.
    const AppliedEdit* nextUndo() const { return undo_.empty() ? nullptr : &undo_.back(); }
    const AppliedEdit* nextRedo() const { return redo_.empty() ? nullptr : &redo_.back(); }

    // Everything done since the journal was last started (a load, a reset), in order.
    const std::vector<JournalEntry>& journal() const { return journal_; }
    bool journalFull() const { return journalFull_; }
    // Forgets the stacks and the journal (a new scene, a new run).
    void clear();

  private:
    void record(JournalEntry entry);
    UndoResult move(EditTarget target, std::uint64_t frame, bool back); // undo or redo
    std::deque<AppliedEdit> undo_;
    std::deque<AppliedEdit> redo_;
    std::vector<JournalEntry> journal_;
    bool journalFull_ = false;
    bool joinable_ = false; // the top of the undo stack may take a continuing edit
};
