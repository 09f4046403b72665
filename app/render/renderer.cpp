#include "renderer.h"

#include "embedded_shaders.h"
#include "gl_shader.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace {

constexpr float kCorners[8] = {-1.f, -1.f, 1.f, -1.f, -1.f, 1.f, 1.f, 1.f};
constexpr double kWallThicknessPx = 10.0;
// Widths of the lines drawn as GL lines (whole pixels; 1 where the context has no wide lines).
constexpr float kTrailWidthPx = 2.0f;
constexpr float kVelocityShaftPx = 3.0f;
constexpr float kMomentumShaftPx = 7.0f;
constexpr double kArrowWidthPx = 2.5; // the fling arrow's shaft (triangles)
constexpr double kArrowHeadPx = 11.0;
constexpr double kGridMinPx = 12.0;

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
    // Wide lines need a context that is not forward-compatible (the window asks for none).
    GLint flags = 0;
    glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
    GLfloat range[2] = {1.0f, 1.0f};
    glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
    maxLineWidth_ =
        (flags & GL_CONTEXT_FLAG_FORWARD_COMPATIBLE_BIT) ? 1.0f : std::max(1.0f, range[1]);
    GLfloat pointSizes[2] = {1.0f, 1.0f};
    glGetFloatv(GL_POINT_SIZE_RANGE, pointSizes);
    maxPointPx_ = std::min(static_cast<double>(pointSizes[1]), kMaxPointSpritePx);

    glGenVertexArrays(1, &blockVao_);
    glGenBuffers(1, &cornerVbo_);
    glGenBuffers(1, &instanceVbo_);
    glBindVertexArray(blockVao_);
    glBindBuffer(GL_ARRAY_BUFFER, cornerVbo_);
    glBufferData(GL_ARRAY_BUFFER, sizeof kCorners, kCorners, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, instanceVbo_);
    const GLsizei stride = sizeof(BlockInstance);
    const struct {
        GLuint index;
        GLint size;
        std::size_t offset;
    } attributes[4] = {{1, 4, offsetof(BlockInstance, rect)},
                       {2, 4, offsetof(BlockInstance, fill)},
                       {3, 4, offsetof(BlockInstance, outline)},
                       {4, 2, offsetof(BlockInstance, style)}};
    for (const auto& a : attributes) {
        glEnableVertexAttribArray(a.index);
        glVertexAttribPointer(a.index, a.size, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(a.offset));
        glVertexAttribDivisor(a.index, 1);
    }
    // The same records as points: one vertex each, no corners.
    glGenVertexArrays(1, &pointVao_);
    glBindVertexArray(pointVao_);
    glBindBuffer(GL_ARRAY_BUFFER, instanceVbo_);
    for (const auto& a : attributes) {
        glEnableVertexAttribArray(a.index);
        glVertexAttribPointer(a.index, a.size, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(a.offset));
    }

    glGenVertexArrays(1, &shapeVao_);
    glGenBuffers(1, &shapeVbo_);
    glBindVertexArray(shapeVao_);
    glBindBuffer(GL_ARRAY_BUFFER, shapeVbo_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(ShapeVertex),
                          reinterpret_cast<const void*>(offsetof(ShapeVertex, x)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(ShapeVertex),
                          reinterpret_cast<const void*>(offsetof(ShapeVertex, r)));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return true;
}

void SceneRenderer::shutdown() {
    glDeleteBuffers(1, &cornerVbo_);
    glDeleteBuffers(1, &instanceVbo_);
    glDeleteBuffers(1, &shapeVbo_);
    glDeleteVertexArrays(1, &blockVao_);
    glDeleteVertexArrays(1, &pointVao_);
    glDeleteVertexArrays(1, &shapeVao_);
    for (auto& shapes : blockPrograms_) {
        for (BlockProgram& b : shapes) {
            if (b.program) glDeleteProgram(b.program);
            b = BlockProgram{};
        }
    }
    if (shapeProgram_) glDeleteProgram(shapeProgram_);
    shapeProgram_ = 0;
    blockVao_ = pointVao_ = shapeVao_ = cornerVbo_ = instanceVbo_ = shapeVbo_ = 0;
}

void SceneRenderer::buildShapes(const SceneView& view) {
    under_.clear();
    momenta_.clear();
    over_.clear();
    addGrid(view);
    if (view.trails) addTrails(view, *view.trails);
    if (view.vectors) addArrows(view);
    if (view.flingActive) {
        const double px = view.camera->pixelsToMetres(1.0);
        over_.arrow(view.flingFrom, view.flingTo, kArrowWidthPx * 1.6 * px, kArrowHeadPx * 1.5 * px,
                    scene_colors::kFling);
    }
}

// The metre grid, limited to what is visible inside the bounds.
void SceneRenderer::addGrid(const SceneView& view) {
    const World& world = *view.world;
    const Camera& cam = *view.camera;
    const double px = cam.pixelsToMetres(1.0);
    const ScreenRect& vp = cam.viewport();
    const Vec2 a = cam.screenToWorld({vp.x, vp.y + vp.height});
    const Vec2 b = cam.screenToWorld({vp.x + vp.width, vp.y});
    const Vec2 lo{std::max(a.x, world.bounds.min.x), std::max(a.y, world.bounds.min.y)};
    const Vec2 hi{std::min(b.x, world.bounds.max.x), std::min(b.y, world.bounds.max.y)};
    if (!(lo.x < hi.x && lo.y < hi.y)) return;
    const double step = gridSpacing(cam.pixelsPerMetre(), kGridMinPx);
    const double major = step * 5.0;
    const double x0 = world.bounds.min.x + std::ceil((lo.x - world.bounds.min.x) / step) * step;
    for (double x = x0; x <= hi.x; x += step) {
        const double m = std::fmod(std::abs(x - world.bounds.min.x) + 1e-9, major);
        const bool isMajor = m < 1e-6;
        under_.rect({x - px * 0.5, lo.y}, {x + px * 0.5, hi.y},
                    isMajor ? scene_colors::kGridMajor : scene_colors::kGridMinor);
    }
    const double y0 = world.bounds.min.y + std::ceil((lo.y - world.bounds.min.y) / step) * step;
    for (double y = y0; y <= hi.y; y += step) {
        const double m = std::fmod(std::abs(y - world.bounds.min.y) + 1e-9, major);
        const bool isMajor = m < 1e-6;
        under_.rect({lo.x, y - px * 0.5}, {hi.x, y + px * 0.5},
                    isMajor ? scene_colors::kGridMajor : scene_colors::kGridMinor);
    }
}

// Trails, fading with age, as GL lines. A software rasteriser pays for every pixel of their
// length, so at most kTrailPixelBudget pixels of trail are drawn: all trails are cut at the same
// age (a crowded scene shows short tails), and with many blocks only every k-th stored point is
// used, to stay within kTrailSegmentBudget segments.
void SceneRenderer::addTrails(const SceneView& view, const Trails& trails) {
    const World& world = *view.world;
    const double px = view.camera->pixelsToMetres(1.0);
    const int oldest = trails.ageWithinLength(world, kTrailPixelBudget * px);
    if (oldest < 1) return;
    std::size_t moving = 0;
    for (const Block& bl : world.blocks) moving += bl.kind != BodyKind::Static;
    const long long wanted = static_cast<long long>(moving) * oldest;
    const int stride = static_cast<int>(
        std::max<long long>(1, (wanted + kTrailSegmentBudget - 1) / kTrailSegmentBudget));
    const auto fade = [oldest](int age) {
        return 0.75f * (1.0f - static_cast<float>(age) / static_cast<float>(oldest + 1));
    };
    for (std::size_t i = 0; i < trails.blockCount(); ++i) {
        if (world.blocks[i].kind == BodyKind::Static) continue;
        const Color c = i < view.blockColors.size() ? view.blockColors[i] : Color{};
        Vec2 prev = trails.point(i, 0);
        int prevAge = 0;
        while (prevAge < oldest) {
            const int age = std::min(prevAge + stride, oldest);
            const Vec2 p = trails.point(i, age);
            under_.segment(prev, p, c.withAlpha(fade(prevAge)), c.withAlpha(fade(age)));
            prev = p;
            prevAge = age;
        }
    }
}

// Momentum arrows (wide, translucent, under) and velocity arrows from the centres of moving
// blocks: p = m·v points the same way as v, so the two share a line.
void SceneRenderer::addArrows(const SceneView& view) {
    const double px = view.camera->pixelsToMetres(1.0);
    std::size_t dynamic = 0;
    for (const Block& bl : view.world->blocks) dynamic += bl.isDynamic();
    const bool heads = dynamic <= kMomentumHeadsUpTo;
    for (const Block& bl : view.world->blocks) {
        if (!bl.isDynamic()) continue;
        const Vec2 tip = bl.position + bl.velocity * (bl.mass * kMomentumArrowScale);
        if (heads)
            momenta_.lineArrow(bl.position, tip, kArrowHeadPx * 1.3 * px, scene_colors::kMomentum);
        else
            momenta_.segment(bl.position, tip, scene_colors::kMomentum);
    }
    for (const Block& bl : view.world->blocks) {
        if (bl.kind == BodyKind::Static) continue;
        const Vec2 tip = bl.position + bl.velocity * kVelocityArrowScale;
        over_.lineArrow(bl.position, tip, kArrowHeadPx * px, scene_colors::kVelocity);
    }
}

void SceneRenderer::buildBlocks(const SceneView& view) {
    const World& world = *view.world;
    const double px = view.camera->pixelsToMetres(1.0);
    for (auto& shapes : blocks_) {
        for (std::vector<BlockInstance>& list : shapes) list.clear();
    }
    const Camera& cam = *view.camera;
    // Each block as a point sprite or a quad (drawsAsPointSprite says which).
    const auto add = [&](BlockStyle style, const BlockInstance& b) {
        const ScreenRect onScreen{0.0, 0.0, view.displayWidth, view.displayHeight};
        const bool point = drawsAsPointSprite(
            2.0 * b.rect[2] * cam.pixelsPerMetre(), 2.0 * b.rect[3] * cam.pixelsPerMetre(),
            cam.worldToScreen({b.rect[0], b.rect[1]}), onScreen, maxPointPx_);
        blocks_[style][point ? kPoint : kQuad].push_back(b);
    };

    // The four walls, just outside the bounds, hatched like every body of infinite mass.
    const double t = kWallThicknessPx * px;
    const Vec2 mn = world.bounds.min, mx = world.bounds.max;
    const Color wall = scene_colors::kWall;
    const Vec2 wallRects[4][2] = {{{mn.x - t, mn.y - t}, {mn.x, mx.y + t}},
                                  {{mx.x, mn.y - t}, {mx.x + t, mx.y + t}},
                                  {{mn.x, mn.y - t}, {mx.x, mn.y}},
                                  {{mn.x, mx.y}, {mx.x, mx.y + t}}};
    for (const auto& r : wallRects) {
        const Vec2 c = (r[0] + r[1]) * 0.5, h = (r[1] - r[0]) * 0.5;
        blocks_[kPatterned][kQuad].push_back({{float(c.x), float(c.y), float(h.x), float(h.y)},
                                              {wall.r, wall.g, wall.b, wall.a},
                                              {wall.r, wall.g, wall.b, wall.a},
                                              {0.0f, 1.0f}});
    }

    for (std::size_t i = 0; i < world.blocks.size(); ++i) {
        const Block& b = world.blocks[i];
        const Color fill = i < view.blockColors.size() ? view.blockColors[i] : Color{};
        const bool selected = static_cast<int>(i) == view.selected;
        const Color outline = selected ? scene_colors::kSelection : scene_colors::kOutline;
        const float pattern = b.kind == BodyKind::Static      ? 1.0f
                              : b.kind == BodyKind::Kinematic ? 2.0f
                                                              : 0.0f;
        add(pattern > 0.0f ? kPatterned : kPlain, {{float(b.position.x), float(b.position.y),
                                                    float(b.size.x * 0.5), float(b.size.y * 0.5)},
                                                   {fill.r, fill.g, fill.b, fill.a},
                                                   {outline.r, outline.g, outline.b, outline.a},
                                                   {selected ? 3.0f : 1.5f, pattern}});
    }

    // Ghosts: outlines only (a transparent fill), in each ghost world's colour.
    for (const SceneView::Ghosts& g : view.ghosts) {
        if (!g.world) continue;
        const Color c = g.color;
        for (const Block& b : g.world->blocks) {
            if (b.kind == BodyKind::Static) continue;
            add(kOutlineOnly, {{float(b.position.x), float(b.position.y), float(b.size.x * 0.5),
                                float(b.size.y * 0.5)},
                               {c.r, c.g, c.b, 0.0f},
                               {c.r, c.g, c.b, 0.95f},
                               {2.0f, 0.0f}});
        }
    }
}

void SceneRenderer::drawVertices(const std::vector<ShapeVertex>& vertices, GLenum mode) {
    if (vertices.empty()) return;
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(ShapeVertex)),
                 vertices.data(), GL_STREAM_DRAW);
    glDrawArrays(mode, 0, static_cast<GLsizei>(vertices.size()));
}

void SceneRenderer::drawShapes(const ClipTransform& t, const ShapeBatch& batch, float lineWidthPx) {
    if (batch.vertices().empty() && batch.segmentVertices().empty()) return;
    glUseProgram(shapeProgram_);
    setUniformTransform(shapeTransform_, t);
    glBindVertexArray(shapeVao_);
    glBindBuffer(GL_ARRAY_BUFFER, shapeVbo_);
    drawVertices(batch.vertices(), GL_TRIANGLES);
    glLineWidth(std::clamp(lineWidthPx, 1.0f, maxLineWidth_));
    drawVertices(batch.segmentVertices(), GL_LINES);
}

void SceneRenderer::draw(const SceneView& view) {
    const Color bg = scene_colors::kBackground;
    glDisable(GL_SCISSOR_TEST);
    glClearColor(bg.r, bg.g, bg.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (!view.world || !view.camera || !shapeProgram_) return;

    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);

    // The arena (inside the bounds) by a scissored clear: far cheaper than a quad on llvmpipe.
    GLint vp[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, vp);
    const double sx = vp[2] / view.displayWidth, sy = vp[3] / view.displayHeight;
    const Vec2 lo = view.camera->worldToScreen(view.world->bounds.min);
    const Vec2 hi = view.camera->worldToScreen(view.world->bounds.max);
    const double x0 = std::max(0.0, lo.x * sx), x1 = std::min(double(vp[2]), hi.x * sx);
    const double y0 = std::max(0.0, vp[3] - lo.y * sy),
                 y1 = std::min(double(vp[3]), vp[3] - hi.y * sy);
    if (x1 > x0 && y0 > y1) {
        const Color arena = scene_colors::kArena;
        glEnable(GL_SCISSOR_TEST);
        glScissor(static_cast<GLint>(std::lround(x0)), static_cast<GLint>(std::lround(y1)),
                  static_cast<GLsizei>(std::lround(x1 - x0)),
                  static_cast<GLsizei>(std::lround(y0 - y1)));
        glClearColor(arena.r, arena.g, arena.b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
    }

    const ClipTransform t = view.camera->clipTransform(view.displayWidth, view.displayHeight);
    buildShapes(view);
    buildBlocks(view);

    drawShapes(t, under_, kTrailWidthPx);

    glEnable(GL_PROGRAM_POINT_SIZE);
    glBindBuffer(GL_ARRAY_BUFFER, instanceVbo_);
    for (int k = 0; k < kBlockStyleCount; ++k) {
        for (int shape = 0; shape < kBlockShapeCount; ++shape) {
            const std::vector<BlockInstance>& instances = blocks_[k][shape];
            const BlockProgram& b = blockPrograms_[k][shape];
            if (instances.empty() || !b.program) continue;
            glUseProgram(b.program);
            setUniformTransform(b.transform, t);
            glUniform1f(b.pixelsPerMetre, static_cast<float>(view.camera->pixelsPerMetre()));
            glBindVertexArray(shape == kPoint ? pointVao_ : blockVao_);
            glBufferData(GL_ARRAY_BUFFER,
                         static_cast<GLsizeiptr>(instances.size() * sizeof(BlockInstance)),
                         instances.data(), GL_STREAM_DRAW);
            const auto n = static_cast<GLsizei>(instances.size());
            if (shape == kPoint)
                glDrawArrays(GL_POINTS, 0, n);
            else
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, n);
        }
    }
    glDisable(GL_PROGRAM_POINT_SIZE);

    drawShapes(t, momenta_, kMomentumShaftPx);
    drawShapes(t, over_, kVelocityShaftPx);

    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glUseProgram(0);
}
