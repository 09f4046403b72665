// The velocity-space picture of two blocks on a line (Galperin 2003, "Playing pool with pi"):
// the state (v1, v2) along the collision axis x drawn at X = (sqrt(m1)·v1, sqrt(m2)·v2). There
//   kinetic energy is a circle:  x² + y² = m1·v1² + m2·v2² = 2·KE (radius |X|),
//   momentum is a line:          sqrt(m1)·x + sqrt(m2)·y = m1·v1 + m2·v2 = p,
// and each collision a reflection: block on block keeps p and, with C = 1, KE, so X goes to the
// other point where the line meets the circle, its mirror image across the line through the
// origin along n = (sqrt(m1), sqrt(m2)) (the component along n is the centre of mass's velocity
// u, kept; the one across it is w = v - u, which becomes -C·w: C < 1 pulls X in toward that
// line). A wall hit (v' = -C·v of one block) flips one coordinate's sign. The two reflection
// lines (n, and the axis of the block that hits the wall) meet at theta = atan(sqrt(m_light /
// m_heavy)); each pair of reflections turns X by 2·theta, and the collisions stop when no
// reflection is left within pi: N = ceil(pi / theta) - 1 collisions (3141 for 1 : 1e6, the digits
// of pi for mass ratios 100^k). Pure logic: the velocity_space overlay draws it.
#pragma once

#include "stats.h"
#include "vec2.h"
#include "world.h"

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

// The two blocks drawn: the scene's two dynamic blocks, in file order (block1 is m1).
struct VelocitySpacePair {
    int block1 = -1, block2 = -1;
    double m1 = 0.0, m2 = 0.0; // kg
    std::string why;           // when not valid: why the picture cannot be drawn
    bool valid() const { return block1 >= 0; }
};
// The pair of `world` (exactly two dynamic blocks), or why not ("...has 3 dynamic blocks...").
VelocitySpacePair velocitySpacePair(const World& world);

// The point for velocities v1, v2 (m/s, along x): (sqrt(m1)·v1, sqrt(m2)·v2), in sqrt(kg)·m/s.
Vec2 velocitySpacePoint(const VelocitySpacePair& pair, double v1, double v2);
// The momentum p = m1·v1 + m2·v2 (kg·m/s) the line through `point` stands for.
double momentumOfPoint(const VelocitySpacePair& pair, Vec2 point);
// The kinetic energy (J) of the circle through `point`: |point|² / 2.
double kineticEnergyOfPoint(Vec2 point);
// A block-block collision with bounciness C in these coordinates: the component along
// (sqrt(m1), sqrt(m2)) kept, the one across it times -C.
Vec2 reflectBlockCollision(const VelocitySpacePair& pair, Vec2 point, double C);
// A wall hit of block 1 (or block 2) with bounciness C: its coordinate times -C.
Vec2 reflectWallHit(Vec2 point, bool firstBlock, double C);
// The angle (rad) between the two reflection lines when the lighter block hits the wall:
// atan(sqrt(m_light / m_heavy)).
double reflectionAngle(const VelocitySpacePair& pair);
// How many collisions (walls included) a light block between a wall and the heavy one makes,
// C = 1: ceil(pi / theta) - 1.
long long predictedCollisions(const VelocitySpacePair& pair);
// The caption under the picture: what the lines are and, for the count, theta and N.
std::string velocitySpaceCaption(const VelocitySpacePair& pair);
// Its last sentence alone, the count: theta and N (what a small window shows).
std::string velocitySpaceCount(const VelocitySpacePair& pair);

// One sample of the path: the time (s) and the two velocities (m/s along x).
struct VelocitySpaceSample {
    double t = 0.0;
    double v1 = 0.0, v2 = 0.0;
};

// The state's path: one sample after every collision of the pair (rebuilt from the frame's
// collision log, so a frame of many collisions shows each reflection) and one at the end of a
// frame when the velocities changed otherwise (forces); at most kMaxSamples, the oldest dropped.
class VelocitySpacePath {
  public:
    static constexpr std::size_t kMaxSamples = 20000;
    void clear();
    // After a step (or at a run's start, with no log): the frame's collisions in order, then the
    // world's state. A different pair (or masses) starts the path again.
    void record(const World& world, const std::vector<CollisionRecord>& log);
    // The timeline went back to `t`: forget what came after.
    void truncateAfter(double t);
    const VelocitySpacePair& pair() const { return pair_; }
    const std::deque<VelocitySpaceSample>& samples() const { return samples_; }
    std::size_t bytes() const { return samples_.size() * sizeof(VelocitySpaceSample); }

  private:
    void push(const VelocitySpaceSample& s);
    VelocitySpacePair pair_;
    std::deque<VelocitySpaceSample> samples_;
};
