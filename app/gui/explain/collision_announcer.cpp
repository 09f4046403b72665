#include "collision_announcer.h"

#include "inspector_format.h"
#include "text_format.h"

std::string collisionSentence(const CollisionRecord& r, const std::string& name1,
                              const std::string& name2) {
    const auto who = [](const std::string& name) { // "m1 = 1 kg" is m1
        const std::size_t stated = name.find(" = ");
        return nameStatesMass(name) && stated != std::string::npos ? name.substr(0, stated) : name;
    };
    const bool wall = r.other < 0;
    const std::string first = who(name1);
    const std::string second = wall ? std::string("the ") + wallName(r.other) : who(name2);
    std::string s = first + " hits " + second + " along " + (r.axis == 0 ? "x" : "y") +
                    " at t = " + formatNumber(r.time) + " s: v1' = " + formatNumber(r.v1After) +
                    " m/s";
    if (!wall) s += ", v2' = " + formatNumber(r.v2After) + " m/s";
    return s;
}

void CollisionAnnouncer::note(const std::vector<CollisionRecord>& frameLog) {
    for (const CollisionRecord& r : frameLog) {
        if (!times_.empty() && r.time < times_.back()) restart(); // time went back
        times_.push_back(r.time);
        last_ = r;
        ++sinceAnnounced_;
    }
    while (!times_.empty() && times_.back() - times_.front() > 1.0) times_.pop_front();
}

void CollisionAnnouncer::restart() {
    times_.clear();
    sinceAnnounced_ = 0;
}

std::string CollisionAnnouncer::announce(double realNow,
                                         const std::function<std::string(int)>& name) {
    if (sinceAnnounced_ == 0 || realNow - lastAnnounced_ < kAnnounceEverySeconds) return "";
    std::string text;
    if (sinceAnnounced_ == 1 || times_.size() <= 1) {
        text =
            collisionSentence(last_, name(last_.block), last_.other >= 0 ? name(last_.other) : "");
    } else {
        text = std::to_string(times_.size()) + " collisions in the last second";
    }
    sinceAnnounced_ = 0;
    lastAnnounced_ = realNow;
    return text;
}
