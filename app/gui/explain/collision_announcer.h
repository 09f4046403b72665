// A collision in words for a screen reader (the browser page's live region, spoken_text.h): the
// inspector's sentence, and the pace of announcements (at most about one a second; a busy scene
// is summed up). Plain logic with no app state: the simulation session keeps an announcer.
#pragma once

#include "stats.h"

#include <deque>
#include <functional>
#include <string>
#include <vector>

// A collision in the inspector's words: "m1 hits m2 along x at t = 0.625 s: v1' = -2 m/s,
// v2' = 4 m/s" (a wall: "m1 hits the left wall along x at t = 1.5 s: v1' = -3 m/s"). A name
// that states its mass goes without it ("m1 = 1 kg" is m1).
std::string collisionSentence(const CollisionRecord& r, const std::string& name1,
                              const std::string& name2);

// The live region's pace: the collisions of each simulated frame go in (note); announce() says
// at most one thing per kAnnounceEverySeconds of real time: the one collision since the last
// announcement in its words, or, when there were more, how many the last simulated second had
// ("37 collisions in the last second").
constexpr double kAnnounceEverySeconds = 1.0;
class CollisionAnnouncer {
  public:
    void note(const std::vector<CollisionRecord>& frameLog);
    // Time went back (a reset, another scene): what was noted is forgotten (note() does it when
    // a collision comes earlier than the last).
    void restart();
    // `realNow`: s of real time; `name`: a block's name by index. "" when nothing is due.
    std::string announce(double realNow, const std::function<std::string(int)>& name);

  private:
    std::deque<double> times_; // world times of the noted collisions within the last second
    long long sinceAnnounced_ = 0;
    CollisionRecord last_;
    double lastAnnounced_ = -1e300;
};
