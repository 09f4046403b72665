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
    return move(target, frame, true);
}

UndoResult EditHistory::redo(EditTarget target, std::uint64_t frame) {
    return move(target, frame, false);
}

UndoResult EditHistory::move(EditTarget target, std::uint64_t frame, bool back) {
    joinable_ = false;
    // Undo moves the last edit from the undo stack to the redo stack, redo the other way.
    auto& from = back ? undo_ : redo_;
    auto& to = back ? redo_ : undo_;
    if (from.empty()) return {};
    const EditError error = back ? undoEdit(target, from.back()) : redoEdit(target, from.back());
    if (!error.empty()) return {nullptr, error};
    to.push_back(std::move(from.back()));
    from.pop_back();
    if (undo_.size() > kMaxUndo) undo_.pop_front();
    record({back ? JournalEntry::What::Undo : JournalEntry::What::Redo, frame, {}, false});
    return {&to.back(), {}};
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
