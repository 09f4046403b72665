#include "edit_history.h"

#include <utility>

namespace {

// The block as the journal names it: by its name when exactly one block has it (and it does not
// read as a place, "blocks[2]"), else by its place.
BlockRef readableRef(const EditTarget& t, const BlockRef& ref) {
    if (ref.index < 0 || ref.index >= static_cast<int>(t.labels.size())) return ref;
    const std::string& name = t.labels[static_cast<std::size_t>(ref.index)].name;
    if (name.empty() || parseRef(name).index >= 0) return ref;
    int named = 0;
    for (const BlockLabel& label : t.labels) named += label.name == name ? 1 : 0;
    return named == 1 ? BlockRef{-1, name} : ref;
}

} // namespace

ApplyResult EditHistory::apply(EditTarget target, const Edit& edit, std::uint64_t frame,
                               bool continues) {
    Edit logged = edit;
    if (edit.kind == Edit::Kind::SetBlock || edit.kind == Edit::Kind::Remove)
        logged.block = readableRef(target, edit.block);
    ApplyResult r = applyEdit(target, edit);
    if (!r.applied) return r;
    redo_.clear();
    const bool joined =
        continues && joinable_ && !undo_.empty() && joinEdits(undo_.back(), *r.applied);
    if (!joined) {
        undo_.push_back(*r.applied);
        if (undo_.size() > kMaxUndo) undo_.pop_front();
    }
    joinable_ = true;
    // A gesture at one frame (a slider dragged while paused) is one line: only its last value
    // counts. Across frames each value stays, marked as continuing (one undo step on replay).
    if (joined && !journal_.empty()) {
        JournalEntry& last = journal_.back();
        if (last.what == JournalEntry::What::Edit && last.frame == frame &&
            editKey(last.edit) == editKey(logged)) {
            last.edit = std::move(logged);
            return r;
        }
    }
    record({JournalEntry::What::Edit, frame, std::move(logged), joined});
    return r;
}

UndoResult EditHistory::undo(EditTarget target, std::uint64_t frame) {
    joinable_ = false;
    if (undo_.empty()) return {};
    const EditError error = undoEdit(target, undo_.back());
    if (!error.empty()) return {nullptr, error};
    redo_.push_back(std::move(undo_.back()));
    undo_.pop_back();
    record({JournalEntry::What::Undo, frame, {}, false});
    return {&redo_.back(), {}};
}

UndoResult EditHistory::redo(EditTarget target, std::uint64_t frame) {
    joinable_ = false;
    if (redo_.empty()) return {};
    const EditError error = redoEdit(target, redo_.back());
    if (!error.empty()) return {nullptr, error};
    undo_.push_back(std::move(redo_.back()));
    redo_.pop_back();
    record({JournalEntry::What::Redo, frame, {}, false});
    return {&undo_.back(), {}};
}

void EditHistory::clear() {
    undo_.clear();
    redo_.clear();
    journal_.clear();
    journalFull_ = false;
    joinable_ = false;
}

void EditHistory::record(JournalEntry entry) {
    if (journal_.size() >= kMaxJournal) {
        journalFull_ = true;
        return;
    }
    journal_.push_back(std::move(entry));
}
