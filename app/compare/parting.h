// Where a student's engine parts from the reference: the reference's collision nearest before
// the first difference (pair, axis, the formula's numbers, the point of impact t = a/b), and,
// when it is in the frame where they part, the student's state just after it against the
// reference's, axis by axis, in the lecture's terms. So it names mistakes the sandbox has no
// switch for (the formula applied on the wrong axis, the formula's sign, a bounciness of its
// own), and says plainly when nothing explains what the trace shows.
#pragma once

#include "match.h"
#include "poi.h"

#include <string>
#include <vector>

// One thing the trace shows at the parting collision (or in the free flight before it).
struct Finding {
    std::string id;    // "wrong-axis", "move-back", ... (docs/compare.md lists them)
    std::string says;  // in the lecture's words, with the numbers
    std::string slide; // the lecture's slide that says what to do ("" when none)
    // Not a mistake: a convention the lecture leaves open (a corner) or rounding (a collision on
    // a frame's boundary).
    bool convention = false;
};

struct PartingCollision {
    bool found = false;          // the reference has a collision of the block by then
    std::int64_t frame = 0;      // the frame it happened in (it ends at frame·dt)
    bool inPartingFrame = false; // in the frame of the first difference
    CollisionRecord record;      // the reference's
    int differing = -1;          // the block that differs first (scene index)
    int block = -1;              // the body of the collision judged (the record's most telling)
    PoiView poi;                 // its point of impact in the parting frame (when valid)
    Vec2 referencePosition, referenceVelocity; // the reference's at the end of the frame
    bool yoursKnown = false;                   // the trace has that frame
    Vec2 yoursPosition, yoursVelocity;
    std::vector<Finding> findings; // empty: nothing in the table explains the trace there
};

// The parting collision of `match` (its first difference) under `settings`.
PartingCollision findPartingCollision(const Scene& scene, const WorldSettings& settings,
                                      const Trace& trace, const RunMatch& match,
                                      const Tolerance& tolerance);
