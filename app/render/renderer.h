// SceneRenderer: draws a World with the project's shaders: the SceneGeometry of a SceneView
// (blocks as instanced quads or point sprites, walls, the metre grid, arrows, trails). It uploads
// and draws, nothing more: labels and panels are ImGui's, drawn afterwards on top.
#pragma once

#include "gl_api.h"
#include "scene_geometry.h"

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

// How a frame's first paint is done, when a planner gives it (ui_frame_base.h): the whole
// framebuffer cleared to the scene's background, the arena's colour or `clear`, then
// `background` painted the scene's background and `arena` the arena's colour.
struct FrameBase {
    enum class Clear { Background, Arena, Colour };
    // false: the whole framebuffer cleared to the scene's background, then all the arena painted
    bool planned = false;
    Clear clearTo = Clear::Background;
    float clear[4] = {0.0f, 0.0f, 0.0f, 1.0f}; // Clear::Colour's
    std::vector<PixelBox> background, arena;
};
// Given the framebuffer pixels the scene draws in besides its background, and its arena (painted
// before the rest of the scene), in rows from the top.
using FrameBasePlanner =
    std::function<FrameBase(int framebufferWidth, int framebufferHeight, const PixelBox& sceneDrawn,
                            const PixelBox& arena)>;

class SceneRenderer {
  public:
    // Compiles the embedded shaders; false with a message when the driver rejects them.
    bool init(std::string* error);
    void shutdown();
    // Clears the framebuffer and draws the scene (GL viewport set by the caller to
    // view.framebufferWidth x view.framebufferHeight).
    void draw(const SceneView& view);
    // Asked each frame how to paint the frame's base (none: the scene's background everywhere).
    void setFrameBasePlanner(FrameBasePlanner planner) { planner_ = std::move(planner); }

  private:
    // A run of shape vertices in the frame's upload: its first vertex and how many.
    struct ShapeRange {
        GLint first = 0;
        GLsizei count = 0;
    };
    // A batch's parts in the upload: its triangles, and its segments as GL lines or (wider than
    // GL draws them) as the quads writeWideLineQuads makes.
    struct BatchRanges {
        ShapeRange triangles, segments;
        bool segmentsAsLines = true;
        float lineWidthPx = 1.0f;
        // Every vertex's alpha 1: drawn without blending (the same pixels).
        bool trianglesOpaque = false, segmentsOpaque = false;
    };
    // Everything the frame draws in one buffer, uploaded by one glBufferData: the blocks'
    // instances (each style and shape's after the other's), then the shapes' vertices. In WebGL
    // each upload crosses to JavaScript and into the browser's GPU process.
    void upload(const float lineWidthPx[3]);
    void append(const void* data, std::size_t bytes);
    BatchRanges addBatch(const ShapeBatch& batch, float lineWidthPx);
    void drawShapes(const ClipTransform& t, const BatchRanges& ranges);
    // A vertex array's attributes moved to `base` bytes into the buffer, only when they are
    // elsewhere (the offsets stay from frame to frame while the block counts do).
    void pointBlockAttributes(int style, int shape, std::size_t base);
    void pointShapeAttributes(std::size_t base);

    // Blocks are drawn in up to six calls, one program per style and shape (block.frag's
    // variants): instanced quads, or point sprites; each has its vertex array.
    struct BlockProgram {
        GLuint program = 0;
        GLint transform = -1, pixelsPerMetre = -1;
        GLuint vao = 0;
        std::size_t base = ~std::size_t(0); // where its attributes point in the buffer (bytes)
        std::size_t at = 0;                 // its instances in this frame's upload (bytes)
        GLsizei count = 0;                  // and how many
    };
    BlockProgram blockPrograms_[kBlockStyleCount][kBlockShapeCount];
    GLuint shapeProgram_ = 0;
    GLuint cornerVbo_ = 0, streamVbo_ = 0;
    GLuint shapeVao_ = 0;
    std::size_t shapeBase_ = ~std::size_t(0); // where the shape attributes point (bytes)
    GLint shapeTransform_ = -1;
    float maxLineWidth_ = 1.0f; // the widest GL line, pixels (1 in WebGL 2)
    double framebufferPixelsPerMetre_ = 1.0;
    BatchRanges batchRanges_[3];        // under, momenta, over
    std::vector<unsigned char> upload_; // the instances, then the shape vertices
    std::size_t shapeBytes_ = 0;        // where the shape vertices start in upload_
    double maxPointPx_ = 1.0;           // the largest point sprite used for a block, pixels
    SceneGeometry geometry_;
    FrameBasePlanner planner_;
    // The frame's base: its clear, the scene's background (outside `drawn` none is needed) and
    // the arena (rows from the top).
    void paintBase(const SceneView& view, const PixelBox& drawn, const PixelBox& arena);
};
