#include "renderer.h"

#include "embedded_shaders.h"
#include "gl_shader.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace {

constexpr float kCorners[8] = {-1.f, -1.f, 1.f, -1.f, -1.f, 1.f, 1.f, 1.f};

bool allOpaque(const std::vector<ShapeVertex>& vertices) {
    return std::all_of(vertices.begin(), vertices.end(),
                       [](const ShapeVertex& v) { return v.a == 1.0f; });
}

// Blending on or off (opaque shapes replace what is under them: blending would give the same
// pixels, and a software rasteriser pays for it in each of them), only when it changes.
void setBlend(bool& on, bool wanted) {
    if (on == wanted) return;
    if (wanted)
        glEnable(GL_BLEND);
    else
        glDisable(GL_BLEND);
    on = wanted;
}

void setUniformTransform(GLint location, const ClipTransform& t) {
    glUniform4f(location, t.scaleX, t.scaleY, t.offsetX, t.offsetY);
}

} // namespace

bool SceneRenderer::init(std::string* error) {
    const std::string styleDefines[kBlockStyleCount] = {"#define PATTERNED\n", "",
                                                        "#define OUTLINE_ONLY\n"};
    for (int k = 0; k < kBlockStyleCount; ++k) {
        for (int shape = 0; shape < kBlockShapeCount; ++shape) {
            const std::string defines =
                styleDefines[k] + (shape == kPoint ? "#define POINT_SPRITE\n" : "");
            BlockProgram& b = blockPrograms_[k][shape];
            b.program = buildProgram(embedded_shaders::block_vert, embedded_shaders::block_frag,
                                     "block", error, defines.c_str());
            if (!b.program) return false;
            b.transform = glGetUniformLocation(b.program, "uTransform");
            b.pixelsPerMetre = glGetUniformLocation(b.program, "uPixelsPerMetre");
        }
    }
    shapeProgram_ =
        buildProgram(embedded_shaders::shape_vert, embedded_shaders::shape_frag, "shape", error);
    if (!shapeProgram_) return false;
    shapeTransform_ = glGetUniformLocation(shapeProgram_, "uTransform");
    GLfloat range[2] = {1.0f, 1.0f};
    glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
    GLfloat pointSizes[2] = {1.0f, 1.0f};
#if SANDBOX_GL_ES
    maxLineWidth_ = std::max(1.0f, range[1]); // WebGL 2: 1 (wider lines are drawn as quads)
    glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, pointSizes);
#else
    // Wide lines need a context that is not forward-compatible (the window asks for none).
    GLint flags = 0;
    glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
    maxLineWidth_ =
        (flags & GL_CONTEXT_FLAG_FORWARD_COMPATIBLE_BIT) ? 1.0f : std::max(1.0f, range[1]);
    glGetFloatv(GL_POINT_SIZE_RANGE, pointSizes);
#endif
    maxPointPx_ = std::min(static_cast<double>(pointSizes[1]), kMaxPointSpritePx);

    glGenBuffers(1, &cornerVbo_);
    glGenBuffers(1, &streamVbo_);
    glBindBuffer(GL_ARRAY_BUFFER, cornerVbo_);
    glBufferData(GL_ARRAY_BUFFER, sizeof kCorners, kCorners, GL_STATIC_DRAW);
    // A vertex array for each block program: a quad's corners (not for points, one vertex each)
    // and the instances' attributes (pointed into the frame's buffer by pointBlockAttributes).
    for (int k = 0; k < kBlockStyleCount; ++k) {
        for (int shape = 0; shape < kBlockShapeCount; ++shape) {
            BlockProgram& b = blockPrograms_[k][shape];
            glGenVertexArrays(1, &b.vao);
            glBindVertexArray(b.vao);
            if (shape == kQuad) {
                glBindBuffer(GL_ARRAY_BUFFER, cornerVbo_);
                glEnableVertexAttribArray(0);
                glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
            }
            for (GLuint index = 1; index <= 4; ++index) {
                glEnableVertexAttribArray(index);
                if (shape == kQuad) glVertexAttribDivisor(index, 1);
            }
        }
    }
    glGenVertexArrays(1, &shapeVao_);
    glBindVertexArray(shapeVao_);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return true;
}

void SceneRenderer::shutdown() {
    glDeleteBuffers(1, &cornerVbo_);
    glDeleteBuffers(1, &streamVbo_);
    glDeleteVertexArrays(1, &shapeVao_);
    for (auto& shapes : blockPrograms_) {
        for (BlockProgram& b : shapes) {
            if (b.program) glDeleteProgram(b.program);
            if (b.vao) glDeleteVertexArrays(1, &b.vao);
            b = BlockProgram{};
        }
    }
    if (shapeProgram_) glDeleteProgram(shapeProgram_);
    shapeProgram_ = 0;
    shapeVao_ = cornerVbo_ = streamVbo_ = 0;
    shapeBase_ = ~std::size_t(0);
}

void SceneRenderer::pointBlockAttributes(int style, int shape, std::size_t base) {
    BlockProgram& b = blockPrograms_[style][shape];
    if (b.base == base) return;
    b.base = base;
    const GLsizei stride = sizeof(BlockInstance);
    const struct {
        GLuint index;
        GLint size;
        std::size_t offset;
    } attributes[4] = {{1, 4, offsetof(BlockInstance, rect)},
                       {2, 4, offsetof(BlockInstance, fill)},
                       {3, 4, offsetof(BlockInstance, outline)},
                       {4, 2, offsetof(BlockInstance, style)}};
    for (const auto& a : attributes)
        glVertexAttribPointer(a.index, a.size, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(base + a.offset));
}

void SceneRenderer::pointShapeAttributes(std::size_t base) {
    if (shapeBase_ == base) return;
    shapeBase_ = base;
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(ShapeVertex),
                          reinterpret_cast<const void*>(base + offsetof(ShapeVertex, x)));
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(ShapeVertex),
                          reinterpret_cast<const void*>(base + offsetof(ShapeVertex, r)));
}

namespace {

void append(std::vector<unsigned char>& upload, const void* data, std::size_t bytes) {
    const auto* from = static_cast<const unsigned char*>(data);
    upload.insert(upload.end(), from, from + bytes);
}

} // namespace

SceneFrame::BatchRanges SceneRenderer::addBatch(SceneFrame& frame, const ShapeBatch& batch,
                                                float lineWidthPx,
                                                double framebufferPixelsPerMetre) const {
    std::vector<unsigned char>& upload = frame.upload;
    const auto vertexAt = [&] {
        return static_cast<GLint>((upload.size() - frame.shapeBytes) / sizeof(ShapeVertex));
    };
    SceneFrame::BatchRanges r;
    r.lineWidthPx = lineWidthPx;
    r.triangles = {vertexAt(), static_cast<GLsizei>(batch.vertices().size())};
    append(upload, batch.vertices().data(), batch.vertices().size() * sizeof(ShapeVertex));
    const std::vector<ShapeVertex>& segments = batch.segmentVertices();
    r.segmentsAsLines = lineWidthPx <= maxLineWidth_;
    r.trianglesOpaque = allOpaque(batch.vertices());
    if (r.segmentsAsLines) {
        r.segments = {vertexAt(), static_cast<GLsizei>(segments.size())};
        append(upload, segments.data(), segments.size() * sizeof(ShapeVertex));
        r.segmentsOpaque = allOpaque(segments);
        return r;
    }
    // No lines this wide (WebGL 2): the quads GL would have rasterised, written into the upload
    // (their colours are their segments' ends').
    const std::size_t quads = wideLineQuadVertices(segments, framebufferPixelsPerMetre);
    r.segments = {vertexAt(), static_cast<GLsizei>(quads)};
    const std::size_t at = upload.size();
    upload.resize(at + quads * sizeof(ShapeVertex));
    writeWideLineQuads(segments, lineWidthPx, framebufferPixelsPerMetre, upload.data() + at);
    r.segmentsOpaque = quads == 0 || allOpaque(segments);
    return r;
}

void SceneRenderer::buildUpload(SceneFrame& frame, double framebufferPixelsPerMetre) const {
    frame.upload.clear();
    for (int k = 0; k < kBlockStyleCount; ++k) {
        for (int shape = 0; shape < kBlockShapeCount; ++shape) {
            const std::vector<BlockInstance>& instances = geometry_.blocks[k][shape];
            SceneFrame::Blocks& b = frame.blocks[k][shape];
            b.count = static_cast<GLsizei>(instances.size());
            b.at = frame.upload.size();
            // Opaque blocks (the usual case) replace what is under them: no blending, which
            // a software rasteriser pays for in every pixel (the same pixels either way).
            b.opaque = std::all_of(instances.begin(), instances.end(), [](const BlockInstance& i) {
                return i.fill[3] == 1.0f && i.outline[3] == 1.0f;
            });
            append(frame.upload, instances.data(), instances.size() * sizeof(BlockInstance));
        }
    }
    frame.shapeBytes = frame.upload.size();
    const ShapeBatch* batches[3] = {&geometry_.under, &geometry_.momenta, &geometry_.over};
    const float lineWidthPx[3] = {kTrailWidthPx, kMomentumShaftPx, kVelocityShaftPx};
    for (int i = 0; i < 3; ++i)
        frame.batches[i] = addBatch(frame, *batches[i], lineWidthPx[i], framebufferPixelsPerMetre);
}

void SceneRenderer::drawShapes(const SceneFrame& frame, const SceneFrame::BatchRanges& r) {
    if (r.triangles.count == 0 && r.segments.count == 0) return;
    glUseProgram(shapeProgram_);
    setUniformTransform(shapeTransform_, frame.transform);
    glBindVertexArray(shapeVao_);
    pointShapeAttributes(frame.shapeBytes);
    bool blend = true; // as submit() leaves it for the shapes
    if (r.triangles.count) {
        setBlend(blend, !r.trianglesOpaque);
        glDrawArrays(GL_TRIANGLES, r.triangles.first, r.triangles.count);
    }
    if (r.segmentsAsLines) glLineWidth(std::max(r.lineWidthPx, 1.0f));
    if (r.segments.count) {
        setBlend(blend, !r.segmentsOpaque);
        glDrawArrays(r.segmentsAsLines ? GL_LINES : GL_TRIANGLES, r.segments.first,
                     r.segments.count);
    }
    setBlend(blend, true);
}

void SceneRenderer::paintBase(const SceneFrame& frame) {
    const Color bg = frame.background, arenaColor = frame.arenaColor;
    glDisable(GL_SCISSOR_TEST);
    FrameBase unplanned; // the background everywhere, then the arena over it
    if (!frame.base.planned && !frame.arena.empty()) unplanned.arena.push_back(frame.arena);
    const FrameBase& base = frame.base.planned ? frame.base : unplanned;
    if (base.clearTo == FrameBase::Clear::Colour)
        glClearColor(base.clear[0], base.clear[1], base.clear[2], base.clear[3]);
    else if (base.clearTo == FrameBase::Clear::Arena)
        glClearColor(arenaColor.r, arenaColor.g, arenaColor.b, 1.0f);
    else
        glClearColor(bg.r, bg.g, bg.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    // Scissored clears (on llvmpipe each a quad Mesa draws), in GL's rows (from the bottom).
    glEnable(GL_SCISSOR_TEST);
    const auto paint = [&](const Color& c, const std::vector<PixelBox>& boxes) {
        glClearColor(c.r, c.g, c.b, 1.0f);
        for (const PixelBox& r : boxes) {
            if (r.empty()) continue;
            glScissor(r.x0, frame.framebufferHeight - r.y1, r.x1 - r.x0, r.y1 - r.y0);
            glClear(GL_COLOR_BUFFER_BIT);
        }
    };
    paint(bg, base.background);
    paint(arenaColor, base.arena);
    glDisable(GL_SCISSOR_TEST);
}

void SceneRenderer::prepare(const SceneView& view, SceneFrame& frame, bool measureDrawn) {
    frame.framebufferWidth = view.framebufferWidth;
    frame.framebufferHeight = view.framebufferHeight;
    frame.background = view.theme->background;
    frame.arenaColor = view.theme->arena;
    frame.drawn = frame.arena = PixelBox{};
    frame.base = FrameBase{};
    frame.drawsWorld = view.world && view.camera && shapeProgram_;
    if (!frame.drawsWorld) return;
    // The arena (inside the bounds), painted with the frame's base (paintBase).
    // The viewport as the caller set it (not asked of GL: in WebGL a query waits for the GPU
    // process).
    const int vp[4] = {0, 0, view.framebufferWidth, view.framebufferHeight};
    const double sx = vp[2] / view.displayWidth, sy = vp[3] / view.displayHeight;
    const Vec2 lo = view.camera->worldToScreen(view.world->bounds.min);
    const Vec2 hi = view.camera->worldToScreen(view.world->bounds.max);
    // In GL's pixels (rows from the bottom): the screen's y runs downwards, so the bounds' top
    // (hi) is the higher row; min/max keep it right for a camera either way up.
    const double x0 = std::max(0.0, std::min(lo.x, hi.x) * sx),
                 x1 = std::min(double(vp[2]), std::max(lo.x, hi.x) * sx);
    const double y0 = std::max(0.0, vp[3] - std::max(lo.y, hi.y) * sy),
                 y1 = std::min(double(vp[3]), vp[3] - std::min(lo.y, hi.y) * sy);
    const bool arenaShown = x1 > x0 && y1 > y0;
    const int arenaBox[4] = {static_cast<int>(std::lround(x0)), static_cast<int>(std::lround(y0)),
                             static_cast<int>(std::lround(x1 - x0)),
                             static_cast<int>(std::lround(y1 - y0))};

    const ClipTransform t = view.camera->clipTransform(view.displayWidth, view.displayHeight);
    frame.transform = t;
    frame.pixelsPerMetre = static_cast<float>(view.camera->pixelsPerMetre());
    const double framebufferPixelsPerMetre = std::abs(t.scaleX) * 0.5 * vp[2];
    geometry_.build(view, maxPointPx_);

    // Where the scene draws (the base beneath it is planned around it): its shapes and blocks,
    // and the arena, in rows from the top.
    if (arenaShown)
        frame.arena = {arenaBox[0], vp[3] - (arenaBox[1] + arenaBox[3]), arenaBox[0] + arenaBox[2],
                       vp[3] - arenaBox[1]};
    if (measureDrawn) {
        PixelBox& drawn = frame.drawn;
        drawn = drawnBox(geometry_, t, vp[2], vp[3], kMomentumShaftPx, 2.0);
        const PixelBox& arena = frame.arena;
        if (!arena.empty()) {
            if (drawn.empty())
                drawn = arena;
            else
                drawn = {std::min(drawn.x0, arena.x0), std::min(drawn.y0, arena.y0),
                         std::max(drawn.x1, arena.x1), std::max(drawn.y1, arena.y1)};
        }
    }
    buildUpload(frame, framebufferPixelsPerMetre);
}

void SceneRenderer::submit(const SceneFrame& frame) {
    paintBase(frame);
    if (!frame.drawsWorld) return;
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    if (!frame.upload.empty()) {
        glBindBuffer(GL_ARRAY_BUFFER, streamVbo_);
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(frame.upload.size()),
                     frame.upload.data(), GL_STREAM_DRAW);
    }

    drawShapes(frame, frame.batches[0]); // under the blocks: the grid, the trails

#if !SANDBOX_GL_ES
    glEnable(GL_PROGRAM_POINT_SIZE); // always on in OpenGL ES
#endif
    for (int k = 0; k < kBlockStyleCount; ++k) {
        for (int shape = 0; shape < kBlockShapeCount; ++shape) {
            const SceneFrame::Blocks& blocks = frame.blocks[k][shape];
            BlockProgram& b = blockPrograms_[k][shape];
            if (blocks.count == 0 || !b.program) continue;
            if (blocks.opaque)
                glDisable(GL_BLEND);
            else
                glEnable(GL_BLEND);
            glUseProgram(b.program);
            setUniformTransform(b.transform, frame.transform);
            glUniform1f(b.pixelsPerMetre, frame.pixelsPerMetre);
            glBindVertexArray(b.vao);
            pointBlockAttributes(k, shape, blocks.at);
            if (shape == kPoint)
                glDrawArrays(GL_POINTS, 0, blocks.count);
            else
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, blocks.count);
        }
    }
#if !SANDBOX_GL_ES
    glDisable(GL_PROGRAM_POINT_SIZE);
#endif
    glEnable(GL_BLEND);

    drawShapes(frame, frame.batches[1]); // the momentum arrows
    drawShapes(frame, frame.batches[2]); // the velocity arrows, the fling arrow

    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glUseProgram(0);
}
