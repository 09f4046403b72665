// What an edit says to people (docs/edits.md): the --verbose line of an edit ("bounciness: 0.5",
// "m2 mass: 4", "add: new 4", "remove: m1") and what an undo or redo changed, with the digits the
// controls panel shows ("bounciness 0.90 -> 0.50", "m2 mass: 4 kg -> 2 kg"). A block is called
// as a student calls it: "m2" for the block named "m2 = 2 kg". Plain logic.
#pragma once

#include "edit.h"

#include <string>
#include <vector>

// What a student calls block `index` of `labels`: its name without a mass written into it
// ("m2 = 2 kg" is m2, text_format.h), its whole name when another block would be called that
// too, its place ("blocks[2]") when it has no name.
std::string spokenBlockName(const std::vector<BlockLabel>& labels, int index);
// The --verbose line of an applied edit (`logged`: as the journal names its block; `index`: the
// block's place, for a block's field), the world and its labels as they are after it:
// "bounciness: 0.5", "m2 mass: 4".
std::string editLogLine(const Edit& logged, int index, const World& world,
                        const std::vector<BlockLabel>& labels);
// What undoing (`undone`) or redoing `applied` changed: "bounciness 0.90 -> 0.50",
// "m2 mass: 4 kg -> 2 kg" (the block as spokenBlockName calls it).
std::string editChangeText(const AppliedEdit& applied, bool undone,
                           const std::vector<BlockLabel>& labels);
// What the world now has after undoing (`undone`) or doing `applied`, as a sentence a screen
// reader says: "bounciness C is now 0.90", "frame rate is now 30 Hz", "m2 mass is now 4 kg",
// "new 4 added", "m1 removed".
std::string editNowText(const AppliedEdit& applied, bool undone,
                        const std::vector<BlockLabel>& labels);
