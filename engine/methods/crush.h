// The crush rule, shared by the perfect and turn-based methods: a dynamic block bouncing back and
// forth between two infinite masses that close in on it (a kinematic platform pushing it into a
// wall, a static block or another platform) collides ever faster, without end, before they meet:
// each bounce off a body moving at w gives it v' = w - C·(v - w) (lecture, "Collisions on a
// Line – Full Formula"), so every round trip adds about (1 + C)·|w| to its speed. After
// kSqueezeBounces such alternating bounces in one substep the block is crushed: its contacts are
// resolved by the rest rule (RestRule::Always), which reverses the platforms that press,
// as a platform reverses on a wall.
#pragma once

#include "world.h"

#include <vector>

class CrushRule {
  public:
    static constexpr int kSqueezeBounces = 16; // alternating bounces between closing anchors
    static constexpr int kWall = -1;           // the `other` of a contact with the bounds

    // Forgets every block's bounces (at the start of a substep). Costs only the entries used.
    void reset(size_t blockCount);

    // Counts a contact of blocks a and `other` (a block index or kWall) along `axis`, their
    // positions along it given (the perfect method's blocks are moved lazily). Returns whether
    // the dynamic body of the contact, against a wall, a static or a kinematic block, has now
    // bounced more than kSqueezeBounces times in a row between two infinite masses that close in
    // on it. Contacts of two dynamic or two infinite masses are not counted.
    bool squeezed(const std::vector<Block>& blocks, int a, int other, int axis, double positionA,
                  double positionOther);

  private:
    // Per block and axis: the infinite mass it last bounced off (a block index or kWall), on
    // which side (+1 above), and how many times in a row it alternated between closing ones.
    struct Bounce {
        int anchor = 0;
        int side = 0;
        int alternations = 0;
    };
    std::vector<Bounce> bounces_; // 2 per block
    std::vector<size_t> used_;    // entries of bounces_ changed since the last reset
};
