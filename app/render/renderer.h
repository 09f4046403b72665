// SceneRenderer: draws a World with the project's shaders: the SceneGeometry of a SceneView
// (blocks as instanced quads or point sprites, walls, the metre grid, arrows, trails). It uploads
// and draws, nothing more: labels and panels are ImGui's, drawn afterwards on top.
#pragma once

#include "gl_api.h"
#include "scene_geometry.h"

#include <string>
#include <vector>

class SceneRenderer {
  public:
    // Compiles the embedded shaders; false with a message when the driver rejects them.
    bool init(std::string* error);
    void shutdown();
    // Clears the framebuffer and draws the scene (GL viewport set by the caller to
    // view.framebufferWidth x view.framebufferHeight).
    void draw(const SceneView& view);

  private:
    // Triangles, then segments as GL lines `lineWidthPx` wide.
    void drawShapes(const ClipTransform& t, const ShapeBatch& batch, float lineWidthPx);
    void drawVertices(const std::vector<ShapeVertex>& vertices, GLenum mode);

    // Blocks are drawn in up to six calls, one program per style and shape (block.frag's
    // variants): instanced quads, or point sprites.
    struct BlockProgram {
        GLuint program = 0;
        GLint transform = -1, pixelsPerMetre = -1;
    };
    BlockProgram blockPrograms_[kBlockStyleCount][kBlockShapeCount];
    GLuint shapeProgram_ = 0;
    GLuint blockVao_ = 0, pointVao_ = 0, cornerVbo_ = 0, instanceVbo_ = 0;
    GLuint shapeVao_ = 0, shapeVbo_ = 0;
    GLint shapeTransform_ = -1;
    float maxLineWidth_ = 1.0f; // the widest GL line, pixels (1 in WebGL 2)
    double framebufferPixelsPerMetre_ = 1.0;
    std::vector<ShapeVertex> wideLineQuads_; // segments as triangles, when lines cannot be wide
    double maxPointPx_ = 1.0;                // the largest point sprite used for a block, pixels
    SceneGeometry geometry_;
};
