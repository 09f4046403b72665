// The frame of reference the scene is seen in (lecture, "Change your frame of reference! Consider
// the velocities relative to the velocity of the center of mass"): the world's (walls at rest),
// or the centre of mass's, where the camera moves with u = (Σ m_i·v_i) / (Σ m_i) and the arrows
// show w_i = v_i - u (the world's walls then drift across the view). Pure logic: the scene view,
// the renderer and the com overlay read it.
#pragma once

#include "vocabulary.h" // ViewFrame and its names
#include "world.h"

#include <string>

// The centre of mass of the dynamic blocks (lecture, "Momentum"): total mass (kg), position
// Σ m·x / Σ m (m) and velocity u = Σ m·v / Σ m (m/s). Not valid without a dynamic block.
struct CentreOfMass {
    bool valid = false;
    double mass = 0.0;
    Vec2 position, velocity;
};
CentreOfMass centreOfMass(const World& world);

// The velocity the frame moves with: u in the centre-of-mass frame (zero when there is no
// dynamic block), zero in the world's.
Vec2 frameVelocity(const World& world, ViewFrame frame);

// The label of a velocity arrow seen in `frame`: the velocity's symbol from the block's name (w1
// for "m1 = 1 kg" in the centre-of-mass frame, v1 in the world's; w or v for other names), then
// the value: signed along x when the motion is along x ("w2 = -2 m/s"), else the vector
// ("w = (1, 2) m/s"). `velocity` is the one seen in the frame (v - u).
std::string frameVelocityLabel(const std::string& blockName, Vec2 velocity, ViewFrame frame);

// How the camera follows the frame. In the centre-of-mass frame it moves with the centre of mass
// (dX/dt = u, so the centre of mass stays still on screen): after a fit, by its displacement
// since the anchor; otherwise by its displacement since the last frame, so panning and zooming
// still work. A run anchors it at its start (the view follows from t = 0, however many frames
// are stepped before the next draw); choosing the frame or F (fit) anchors it where it is then.
struct FrameCamera {
    bool anchored = false;
    Vec2 anchor; // m, the centre of mass when the view was fitted, the frame chosen or a run began
    Vec2 last;   // m, the centre of mass the camera followed last frame
};
// Anchors `follow` at `world`'s centre of mass now (unanchored without a dynamic block).
void anchorFrameCamera(FrameCamera& follow, const World& world);
// The shift (m) to add to the camera's centre this frame (zero in the world's frame); `fitted`:
// the camera was just fitted to the world (its centre is the fit's). Anchors first if needed.
Vec2 followShift(FrameCamera& follow, const World& world, ViewFrame frame, bool fitted);
