// SceneRenderer: draws a World with the project's shaders (blocks as instanced quads, walls, the
// metre grid, velocity arrows, trails). It reads what to draw and draws, nothing more: labels
// and panels are ImGui's, drawn afterwards on top.
#pragma once

#include "camera.h"
#include "gl_api.h"
#include "palette.h"
#include "shape_batch.h"
#include "trails.h"
#include "world.h"

#include <string>
#include <vector>

struct SceneView {
    const World* world = nullptr;
    const Camera* camera = nullptr;
    std::vector<Color> blockColors; // per block (palette or scene colour)
    double displayWidth = 1280.0;   // screen pixels of the whole framebuffer
    double displayHeight = 720.0;
    int selected = -1;
    const Trails* trails = nullptr; // drawn when set
    bool vectors = false;           // velocity and momentum arrows
    // Other worlds drawn as coloured outlines over this one (the methods side by side).
    struct Ghosts {
        const World* world = nullptr;
        Color color;
    };
    std::vector<Ghosts> ghosts;
    bool flingActive = false; // the fling arrow while right-dragging
    Vec2 flingFrom, flingTo;
};

// Velocity arrows: metres of arrow per m/s; momentum arrows: metres per kg·m/s.
constexpr double kVelocityArrowScale = 0.25;
constexpr double kMomentumArrowScale = 0.15;
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

class SceneRenderer {
  public:
    // Compiles the embedded shaders; false with a message when the driver rejects them.
    bool init(std::string* error);
    void shutdown();
    // Clears the framebuffer and draws the scene (GL viewport set by the caller).
    void draw(const SceneView& view);

  private:
    struct BlockInstance {
        float rect[4]; // centre xy, half size zw
        float fill[4];
        float outline[4];
        float style[2]; // outline px, pattern
    };
    void buildShapes(const SceneView& view);
    void addGrid(const SceneView& view);
    void addTrails(const SceneView& view, const Trails& trails);
    void addArrows(const SceneView& view);
    void buildBlocks(const SceneView& view);
    // Triangles, then segments as GL lines `lineWidthPx` wide.
    void drawShapes(const ClipTransform& t, const ShapeBatch& batch, float lineWidthPx);
    void drawVertices(const std::vector<ShapeVertex>& vertices, GLenum mode);

    // Blocks are drawn in up to six calls, one program each (block.frag's variants): walls and
    // infinite masses with their pattern, moving blocks plain, ghosts as outlines; each as
    // instanced quads, or as point sprites when small (see buildBlocks).
    enum BlockStyle { kPatterned, kPlain, kOutlineOnly, kBlockStyleCount };
    enum BlockShape { kQuad, kPoint, kBlockShapeCount };
    struct BlockProgram {
        GLuint program = 0;
        GLint transform = -1, pixelsPerMetre = -1;
    };
    BlockProgram blockPrograms_[kBlockStyleCount][kBlockShapeCount];
    GLuint shapeProgram_ = 0;
    GLuint blockVao_ = 0, pointVao_ = 0, cornerVbo_ = 0, instanceVbo_ = 0;
    GLuint shapeVao_ = 0, shapeVbo_ = 0;
    GLint shapeTransform_ = -1;
    ShapeBatch under_;   // grid, trails
    ShapeBatch momenta_; // momentum arrows, over the blocks
    ShapeBatch over_;    // velocity arrows, the fling arrow
    float maxLineWidth_ = 1.0f;
    double maxPointPx_ = 1.0; // the largest point sprite used for a block, pixels
    std::vector<BlockInstance> blocks_[kBlockStyleCount][kBlockShapeCount];
};
