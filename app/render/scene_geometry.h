// SceneGeometry: what the scene renderer draws, built on the CPU each frame from a SceneView
// without any GL: the shape batches (grid, trails, arrows) and the block instances sorted by
// style and by shape (quad or point sprite). Its rules keep the primitive count low, since a
// software rasteriser (llvmpipe) pays about the same for each primitive however small: see the
// constants below. SceneRenderer uploads and draws it.
#pragma once

#include "camera.h"
#include "palette.h"
#include "shape_batch.h"
#include "trails.h"
#include "world.h"

#include <cstddef>
#include <vector>

struct SceneView {
    const World* world = nullptr;
    const Camera* camera = nullptr;
    std::vector<Color> blockColors; // per block (palette or scene colour)
    double displayWidth = 1280.0;   // screen pixels of the whole framebuffer
    double displayHeight = 720.0;
    int framebufferWidth = 1280; // the GL viewport the scene is drawn into (device pixels)
    int framebufferHeight = 720;
    int selected = -1;
    const Trails* trails = nullptr; // drawn when set
    bool vectors = false;           // velocity, momentum and force arrows
    Vec2 frameVelocity;             // m/s, subtracted from every arrow (the frame moves with it)
    // The keys' push (N) on block `thrustBlock` this frame (-1: none): the thrust or a player's
    // move force, added to its own force; its force arrow is drawn with or without `vectors`.
    int thrustBlock = -1;
    Vec2 thrust;
    // Other worlds drawn as coloured outlines over this one (the methods side by side).
    struct Ghosts {
        const World* world = nullptr;
        Color color;
    };
    std::vector<Ghosts> ghosts;
    const SceneTheme* theme = &sceneTheme(false); // colours (blocks are outlined against arena)
    bool flingActive = false;                     // the fling arrow while right-dragging
    Vec2 flingFrom, flingTo;
};

// Velocity arrows: metres of arrow per m/s; momentum arrows: metres per kg·m/s.
constexpr double kVelocityArrowScale = 0.25;
constexpr double kMomentumArrowScale = 0.15;

// Force arrows (lecture, "Newton's 2nd law", F = m·a): metres of arrow per newton.
constexpr double kForceArrowScale = 0.75;
// The force arrow block `index` of `view` shows (N): its own force plus the thrust on it; zero
// when none is drawn (no force, or arrows off and no thrust on it).
Vec2 shownForce(const SceneView& view, std::size_t index);

// Long arrows keep their heads on screen: up to the knee (a share of the viewport's smaller side)
// an arrow is drawn to scale; beyond it, its length grows with the logarithm (at most twice the
// knee), and it is cut at the viewport's edge and at the arena's walls (it does not leave the
// arena nor the screen); the label then gives the value (300 m/s, 19.6 kg·m/s).
constexpr double kArrowKneeShare = 0.22;
struct ArrowOnScreen {
    Vec2 tip;            // m, where the head is drawn
    bool toScale = true; // false: compressed or cut, so the label must give the value
};
// The drawn length (px) of an arrow `lengthPx` long to scale, for a knee of `kneePx`.
double displayedArrowPx(double lengthPx, double kneePx);
// The arrow from `from` along `vector` (m, to scale) as drawn through `camera`, its head inside
// the viewport and, given, inside `arena` (the world's bounds) where `from` is.
ArrowOnScreen arrowOnScreen(const Camera& camera, Vec2 from, Vec2 vector,
                            const Bounds* arena = nullptr);
// What arrowOnScreen works out of the camera and the arena alone, once for the arrows of a frame
// (a gas draws two thousand): arrows(from, vector) is arrowOnScreen(camera, from, vector, arena),
// bit for bit. The camera and the arena must not change while it is used.
class ArrowsOnScreen {
  public:
    ArrowsOnScreen(const Camera& camera, const Bounds* arena = nullptr);
    ArrowOnScreen operator()(Vec2 from, Vec2 vector) const;

  private:
    const Camera& camera_;
    double knee_;         // px (displayedArrowPx)
    double limits_[2][2]; // px: along x and y, the least and the most the head may reach
};
// Blocks up to this size on screen (pixels) may be drawn as point sprites.
constexpr double kMaxPointSpritePx = 64.0;
// With more moving blocks than this, momentum arrows are drawn without heads (the velocity arrow
// over each shows the same direction): a software rasteriser pays about as much for each small
// triangle as for a large one.
constexpr std::size_t kMomentumHeadsUpTo = 300;
// Trails draw at most about this many pixels of length in all (cut at the same age: shorter tails
// in a crowded scene) and this many segments (older points thinned out).
constexpr double kTrailPixelBudget = 30000.0;
constexpr int kTrailSegmentBudget = 2500;

// Widths of what is drawn as GL lines, in pixels (whole pixels; the renderer draws 1 px where
// the context has no wide lines).
constexpr float kTrailWidthPx = 2.0f;
constexpr float kVelocityShaftPx = 3.0f;
constexpr float kMomentumShaftPx = 7.0f;

// One block as the block shaders read it (an instance of a quad, or a point).
struct BlockInstance {
    float rect[4]; // centre xy, half size zw (m)
    float fill[4];
    float outline[4];
    float style[2]; // outline width (px), pattern (0 none, 1 hatched, 2 striped)
};
// Which variant of block.frag draws a block: walls and infinite masses with their pattern,
// moving blocks plain, the other methods' ghosts as outlines.
enum BlockStyle { kPatterned, kPlain, kOutlineOnly, kBlockStyleCount };
enum BlockShape { kQuad, kPoint, kBlockShapeCount };

// Framebuffer pixels [x0, x1) x [y0, y1), rows counted from the top.
struct PixelBox {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
};

struct SceneGeometry {
    ShapeBatch under;   // grid, trails (segments kTrailWidthPx wide)
    ShapeBatch momenta; // momentum arrows, over the blocks (shafts kMomentumShaftPx wide)
    ShapeBatch over;    // velocity arrows (shafts kVelocityShaftPx wide), the fling arrow
    std::vector<BlockInstance> blocks[kBlockStyleCount][kBlockShapeCount];

    // Rebuilds everything for `view`; blocks become point sprites where drawsAsPointSprite
    // allows with sprites up to `maxPointPx` (1: never).
    void build(const SceneView& view, double maxPointPx);

  private:
    void addGrid(const SceneView& view);
    void addTrails(const SceneView& view, const Trails& trails);
    void addArrows(const SceneView& view);
    void addBlocks(const SceneView& view, double maxPointPx);

    // A fill's outline against an arena and whether it is faint there (outlineFor and
    // contrastRatio: a dozen pow() calls, once per colour rather than per block and frame).
    struct OutlineOf {
        Color fill, arena, outline;
        bool faint = false;
    };
    std::vector<OutlineOf> outlines_;
    const OutlineOf& outlineOf(const Color& fill, const Color& arena);
    // addTrails' steps (the same ages for every block), kept from frame to frame.
    struct TrailStep {
        int slot;           // the ring's slot of the step's older point
        bool throughImpact; // a point of impact kept on the way may be drawn through
        float alpha, mid;   // the older point's fade; half way between it and the newer one's
    };
    std::vector<TrailStep> trailSteps_;
};

// A box holding every framebuffer pixel that drawing `geometry` through `t` into a width x height
// framebuffer may touch (quads, point sprites with their 2 px of margin, triangles, and lines up
// to `lineWidthPx` wide), `marginPx` more on every side, within the framebuffer; empty when
// nothing is drawn.
PixelBox drawnBox(const SceneGeometry& geometry, const ClipTransform& t, int width, int height,
                  double lineWidthPx, double marginPx);
