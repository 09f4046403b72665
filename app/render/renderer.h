// SceneRenderer: draws a World with the project's shaders: the SceneGeometry of a SceneView
// (blocks as instanced quads or point sprites, walls, the metre grid, arrows, trails). It uploads
// and draws, nothing more: labels and panels are ImGui's, drawn afterwards on top.
#pragma once

#include "gl_api.h"
#include "scene_geometry.h"

#include <cstddef>
#include <string>
#include <vector>

// How a frame's first paint is done, when the frame's UI plans it (ui_frame_base.h): the whole
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

// A run of shape vertices in a frame's upload: its first vertex and how many.
struct ShapeRange {
    GLint first = 0;
    GLsizei count = 0;
};

// A frame's scene as SceneRenderer::prepare works it out, with no GL call, and as
// SceneRenderer::submit draws it: the app may prepare frame N+1 on one thread while another
// submits frame N (app/gui/platform/frame). Everything the GL calls need is here.
struct SceneFrame {
    // A batch's parts in the upload: its triangles, and its segments as GL lines or (wider than
    // GL draws them) as the quads writeWideLineQuads makes.
    struct BatchRanges {
        ShapeRange triangles, segments;
        bool segmentsAsLines = true;
        float lineWidthPx = 1.0f;
        // Every vertex's alpha 1: drawn without blending (the same pixels).
        bool trianglesOpaque = false, segmentsOpaque = false;
    };
    // One style and shape of blocks: its instances in the upload (bytes), how many, and whether
    // all are opaque (drawn without blending).
    struct Blocks {
        std::size_t at = 0;
        GLsizei count = 0;
        bool opaque = true;
    };
    bool drawsWorld = false; // else only the base (no world, camera or programs)
    int framebufferWidth = 0, framebufferHeight = 0;
    Color background, arenaColor;
    // Rows from the top: the pixels the scene draws in besides its background (when asked for:
    // the frame base's plan needs them) and its arena.
    PixelBox drawn, arena;
    FrameBase base; // as planned after prepare (else the background, then the arena)
    ClipTransform transform;
    float pixelsPerMetre = 1.0f; // the camera's
    // Everything the frame draws in one buffer, uploaded by one glBufferData: the blocks'
    // instances (each style and shape's after the other's), then the shapes' vertices. In WebGL
    // each upload crosses to JavaScript and into the browser's GPU process.
    std::vector<unsigned char> upload;
    std::size_t shapeBytes = 0; // where the shape vertices start in `upload`
    Blocks blocks[kBlockStyleCount][kBlockShapeCount];
    BatchRanges batches[3]; // under, momenta, over
};

class SceneRenderer {
  public:
    // Compiles the embedded shaders; false with a message when the driver rejects them.
    bool init(std::string* error);
    void shutdown();
    // Works out the frame: the scene's geometry and its upload, with no GL call (any thread,
    // one prepare at a time). `measureDrawn`: find frame.drawn, for a plan of the frame's base.
    void prepare(const SceneView& view, SceneFrame& frame, bool measureDrawn);
    // Clears the framebuffer and draws the prepared frame (GL viewport set by the caller to
    // frame.framebufferWidth x frame.framebufferHeight).
    void submit(const SceneFrame& frame);

  private:
    // The frame's upload (SceneFrame::upload) from geometry_.
    void buildUpload(SceneFrame& frame, double framebufferPixelsPerMetre) const;
    SceneFrame::BatchRanges addBatch(SceneFrame& frame, const ShapeBatch& batch, float lineWidthPx,
                                     double framebufferPixelsPerMetre) const;
    void drawShapes(const SceneFrame& frame, const SceneFrame::BatchRanges& ranges);
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
    };
    BlockProgram blockPrograms_[kBlockStyleCount][kBlockShapeCount];
    GLuint shapeProgram_ = 0;
    GLuint cornerVbo_ = 0, streamVbo_ = 0;
    GLuint shapeVao_ = 0;
    std::size_t shapeBase_ = ~std::size_t(0); // where the shape attributes point (bytes)
    GLint shapeTransform_ = -1;
    float maxLineWidth_ = 1.0f; // the widest GL line, pixels (1 in WebGL 2)
    double maxPointPx_ = 1.0;   // the largest point sprite used for a block, pixels
    SceneGeometry geometry_;    // prepare's (its buffers kept from frame to frame)
    // The frame's base: its clear, the scene's background (outside `drawn` none is needed) and
    // the arena (rows from the top).
    void paintBase(const SceneFrame& frame);
};
