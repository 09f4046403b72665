// What an edit says to people (docs/edits.md): the --verbose line of an edit ("bounciness: 0.5",
// "m2.mass: 4", "add: new 4", "remove: m1") and what an undo or redo changed, with the digits the
// controls panel shows ("bounciness 0.90 -> 0.50", "m2 mass 4 kg -> 2 kg"). Plain logic.
#pragma once

#include "edit.h"

#include <string>
#include <vector>

// The --verbose line of an applied edit (`logged`: as the journal names its block), the world
// as it is after it.
std::string editLogLine(const Edit& logged, const World& world);
// What undoing (`undone`) or redoing `applied` changed: "bounciness 0.90 -> 0.50"; the block
// named by `labels` (its name, else its place).
std::string editChangeText(const AppliedEdit& applied, bool undone,
                           const std::vector<BlockLabel>& labels);
