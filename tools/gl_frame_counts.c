// What llvmpipe is given per frame, counted (issue 42): an LD_PRELOAD library for
// sandbox-offscreen that passes every GL call on to libOSMesa and counts, per frame (a frame ends
// at glFinish), the draw calls, primitives and their pixels by what draws them, the buffer
// uploads and the clears. Counts, not times: they do not depend on the machine's load.
// Build and run (docs/performance.md):
//   cc -O2 -shared -fPIC -o /tmp/gl_frame_counts.so tools/gl_frame_counts.c -ldl -lm
//   env -u DISPLAY LD_PRELOAD=/tmp/gl_frame_counts.so GLC_SKIP=10 GLC_DUMP=15
//       build/app/gui/sandbox-offscreen SCENE --benchmark-frames 20 --show LIST
// Prints to stderr at exit the mean per frame over the frames after the first GLC_SKIP (default
// 10, counting the benchmark's settling frames); with GLC_DUMP=N also every draw call of frame N.
// Programs are numbered in the order they were linked: 1 and 2 the UI's (solid, textured), 3 to 8
// the blocks' (patterned, plain, outline-only; quad then point sprite each), 9 the shapes'.
// Pixels are estimates: a triangle's area (UI triangles scaled by the share of their bounding
// box inside the scissor), a line's length times its width, a block's rectangle, a point's square.
// Experiments (pixels change; with callgrind they show what each part costs the rasteriser):
// GLC_DROP=LIST leaves out the draws of the listed programs, GLC_BREAK_RECTS=1 splits every UI
// draw so that no index count is a multiple of 6.
#define _GNU_SOURCE
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NEXT(name) ((__typeof__(&name))dlsym(RTLD_NEXT, #name))

enum { kMaxIds = 4096, kMaxPrograms = 64 };

typedef struct {
    unsigned char* data;
    size_t size;
} Shadow;

static Shadow buffers[kMaxIds];
static GLuint arrayBuffer, elementBuffer, program;
static int programOrdinal[kMaxIds], programsLinked;
static float transform[kMaxPrograms][4];
static int blend = 0, scissorOn = 0;
static GLint scissor[4], viewport[4];
static float lineWidth = 1.0f;
static int frame = 0, skip = 10, dump = -1;

// One class of work: draws, primitives, pixels.
typedef struct {
    const char* name;
    double draws, primitives, pixels;
} Tally;

enum {
    kUiGlyph,
    kUiSolidOpaque,
    kUiSolidTranslucent,
    kUiFeather,
    kUiOther,
    kSceneTriangles,
    kSceneLines,
    kBlockQuads,
    kBlockPoints,
    kClears,
    kArrayUploads,
    kElementUploads,
    kSubUploads,
    kTallies
};
static Tally tallies[kTallies] = {{"UI glyphs/textured tris", 0, 0, 0},
                                  {"UI solid opaque tris", 0, 0, 0},
                                  {"UI solid translucent tris", 0, 0, 0},
                                  {"UI AA feather tris", 0, 0, 0},
                                  {"UI other", 0, 0, 0},
                                  {"scene shape tris", 0, 0, 0},
                                  {"scene lines", 0, 0, 0},
                                  {"block quads (instances)", 0, 0, 0},
                                  {"block points", 0, 0, 0},
                                  {"clears (px)", 0, 0, 0},
                                  {"glBufferData ARRAY (bytes)", 0, 0, 0},
                                  {"glBufferData ELEMENT (bytes)", 0, 0, 0},
                                  {"glBufferSubData (bytes)", 0, 0, 0}};
static double blendedPixels, unblendedPixels, programSwitches, scissorCalls;

// GLC_DROP=LIST (an experiment, pixels change): the draws of these programs (ordinals, comma
// separated; "lines" and "tris" for the shape program's GL_LINES and GL_TRIANGLES) not drawn, to
// see what each costs the rasteriser.
static int dropped(int ordinal, const char* kind) {
    const char* list = getenv("GLC_DROP");
    if (!list) return 0;
    char word[32];
    snprintf(word, sizeof word, "%d", ordinal);
    for (const char* p = list; *p;) {
        const size_t n = strcspn(p, ",");
        if ((strlen(word) == n && strncmp(p, word, n) == 0) ||
            (kind && strlen(kind) == n && strncmp(p, kind, n) == 0))
            return 1;
        p += n + (p[n] == ',');
    }
    return 0;
}

static int counting(void) {
    return frame >= skip;
}
static int dumping(void) {
    return frame == dump;
}

__attribute__((constructor)) static void start(void) {
    const char* s = getenv("GLC_SKIP");
    if (s) skip = atoi(s);
    const char* d = getenv("GLC_DUMP");
    if (d) dump = atoi(d);
}

__attribute__((destructor)) static void finish(void) {
    const int frames = frame - skip;
    if (frames <= 0) return;
    fprintf(stderr, "gl_frame_counts: mean per frame over %d frames (after %d)\n", frames, skip);
    fprintf(stderr, "  %-30s %10s %12s %14s\n", "what", "calls", "primitives", "pixels/bytes");
    for (int i = 0; i < kTallies; ++i)
        fprintf(stderr, "  %-30s %10.1f %12.1f %14.0f\n", tallies[i].name,
                tallies[i].draws / frames, tallies[i].primitives / frames,
                tallies[i].pixels / frames);
    fprintf(stderr,
            "  pixels drawn blended %.0f, unblended %.0f; program switches %.1f, scissor "
            "calls %.1f\n",
            blendedPixels / frames, unblendedPixels / frames, programSwitches / frames,
            scissorCalls / frames);
}

static void add(int what, double draws, double primitives, double pixels) {
    if (!counting()) return;
    tallies[what].draws += draws;
    tallies[what].primitives += primitives;
    tallies[what].pixels += pixels;
}

static void addPixels(double pixels) {
    if (!counting()) return;
    if (blend)
        blendedPixels += pixels;
    else
        unblendedPixels += pixels;
}

static int ordinal(void) {
    return program < kMaxIds ? programOrdinal[program] : 0;
}

// Clip coordinates of world/UI point (x, y) under the current program's transform, to pixels.
static void toPixels(float x, float y, double* px, double* py) {
    const int o = ordinal();
    const float* t = transform[o < kMaxPrograms ? o : 0];
    const double cx = x * t[0] + t[2], cy = y * t[1] + t[3];
    *px = (cx + 1.0) * 0.5 * viewport[2];
    *py = (cy + 1.0) * 0.5 * viewport[3];
}

static double triangleArea(double ax, double ay, double bx, double by, double cx, double cy) {
    return 0.5 * fabs((bx - ax) * (cy - ay) - (cx - ax) * (by - ay));
}

// The share of the box [x0,x1]x[y0,y1] (pixels, y up) inside the scissor, when it is on.
static double scissorShare(double x0, double y0, double x1, double y1) {
    if (!scissorOn) return 1.0;
    const double w = x1 - x0, h = y1 - y0;
    if (w <= 0 || h <= 0) return 0.0;
    const double ix = fmin(x1, scissor[0] + scissor[2]) - fmax(x0, scissor[0]);
    const double iy = fmin(y1, scissor[1] + scissor[3]) - fmax(y0, scissor[1]);
    return ix > 0 && iy > 0 ? ix * iy / (w * h) : 0.0;
}

// ---- state -------------------------------------------------------------------------------------

GLuint glCreateProgram(void) {
    const GLuint p = NEXT(glCreateProgram)();
    if (p < kMaxIds) programOrdinal[p] = ++programsLinked;
    return p;
}

void glUseProgram(GLuint p) {
    if (p != program && p && counting()) programSwitches += 1;
    program = p;
    NEXT(glUseProgram)(p);
}

void glUniform4f(GLint location, GLfloat a, GLfloat b, GLfloat c, GLfloat d) {
    const int o = ordinal();
    if (o > 0 && o < kMaxPrograms) {
        transform[o][0] = a, transform[o][1] = b, transform[o][2] = c, transform[o][3] = d;
    }
    NEXT(glUniform4f)(location, a, b, c, d);
}

void glBindBuffer(GLenum target, GLuint buffer) {
    if (target == GL_ARRAY_BUFFER) arrayBuffer = buffer;
    if (target == GL_ELEMENT_ARRAY_BUFFER) elementBuffer = buffer;
    NEXT(glBindBuffer)(target, buffer);
}

// The element buffer belongs to the VAO: a VAO bound brings its own (the UI's is the only one).
void glBindVertexArray(GLuint vao) {
    NEXT(glBindVertexArray)(vao);
    GLint bound = 0;
    NEXT(glGetIntegerv)(GL_ELEMENT_ARRAY_BUFFER_BINDING, &bound);
    elementBuffer = (GLuint)bound;
}

static void keep(GLuint id, GLsizeiptr offset, GLsizeiptr size, const void* data, int whole) {
    if (id >= kMaxIds) return;
    Shadow* s = &buffers[id];
    if (whole || (size_t)(offset + size) > s->size) {
        s->data = realloc(s->data, (size_t)(offset + size));
        s->size = (size_t)(offset + size);
    }
    if (data) memcpy(s->data + offset, data, (size_t)size);
}

void glBufferData(GLenum target, GLsizeiptr size, const void* data, GLenum usage) {
    const GLuint id = target == GL_ARRAY_BUFFER ? arrayBuffer : elementBuffer;
    keep(id, 0, size, data, 1);
    add(target == GL_ARRAY_BUFFER ? kArrayUploads : kElementUploads, 1, 0, (double)size);
    NEXT(glBufferData)(target, size, data, usage);
}

void glBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, const void* data) {
    const GLuint id = target == GL_ARRAY_BUFFER ? arrayBuffer : elementBuffer;
    keep(id, offset, size, data, 0);
    add(kSubUploads, 1, 0, (double)size);
    NEXT(glBufferSubData)(target, offset, size, data);
}

void glEnable(GLenum cap) {
    if (cap == GL_BLEND) blend = 1;
    if (cap == GL_SCISSOR_TEST) scissorOn = 1;
    NEXT(glEnable)(cap);
}

void glDisable(GLenum cap) {
    if (cap == GL_BLEND) blend = 0;
    if (cap == GL_SCISSOR_TEST) scissorOn = 0;
    NEXT(glDisable)(cap);
}

void glScissor(GLint x, GLint y, GLsizei w, GLsizei h) {
    scissor[0] = x, scissor[1] = y, scissor[2] = w, scissor[3] = h;
    if (counting()) scissorCalls += 1;
    NEXT(glScissor)(x, y, w, h);
}

void glViewport(GLint x, GLint y, GLsizei w, GLsizei h) {
    viewport[0] = x, viewport[1] = y, viewport[2] = w, viewport[3] = h;
    NEXT(glViewport)(x, y, w, h);
}

void glLineWidth(GLfloat w) {
    lineWidth = w;
    NEXT(glLineWidth)(w);
}

void glClear(GLbitfield mask) {
    const double px =
        scissorOn ? (double)scissor[2] * scissor[3] : (double)viewport[2] * viewport[3];
    add(kClears, 1, 0, px);
    if (dumping()) fprintf(stderr, "frame %d: clear %.0f px\n", frame, px);
    NEXT(glClear)(mask);
}

void glFinish(void) {
    NEXT(glFinish)();
    ++frame;
}

// ---- draws -------------------------------------------------------------------------------------

// The scene's shape vertices: x, y (m), r, g, b, a.
typedef struct {
    float x, y, r, g, b, a;
} ShapeVertex;

// The block shaders' instances (BlockInstance).
typedef struct {
    float rect[4], fill[4], outline[4], style[2];
} BlockInstance;

static void sceneArrays(GLenum mode, GLint first, GLsizei count) {
    const Shadow* s = arrayBuffer < kMaxIds ? &buffers[arrayBuffer] : NULL;
    const ShapeVertex* v = s && s->data ? (const ShapeVertex*)s->data + first : NULL;
    double pixels = 0.0, primitives = 0.0;
    if (mode == GL_TRIANGLES) {
        for (GLsizei i = 0; v && i + 2 < count; i += 3) {
            double ax, ay, bx, by, cx, cy;
            toPixels(v[i].x, v[i].y, &ax, &ay);
            toPixels(v[i + 1].x, v[i + 1].y, &bx, &by);
            toPixels(v[i + 2].x, v[i + 2].y, &cx, &cy);
            pixels += triangleArea(ax, ay, bx, by, cx, cy);
        }
        primitives = count / 3;
        add(kSceneTriangles, 1, primitives, pixels);
    } else if (mode == GL_LINES) {
        for (GLsizei i = 0; v && i + 1 < count; i += 2) {
            double ax, ay, bx, by;
            toPixels(v[i].x, v[i].y, &ax, &ay);
            toPixels(v[i + 1].x, v[i + 1].y, &bx, &by);
            pixels += fmax(fabs(bx - ax), fabs(by - ay)) * lineWidth;
        }
        primitives = count / 2;
        add(kSceneLines, 1, primitives, pixels);
    } else if (mode == GL_POINTS) { // the block point sprites
        const BlockInstance* b = s && s->data ? (const BlockInstance*)s->data + first : NULL;
        const int o = ordinal();
        const float* t = transform[o < kMaxPrograms ? o : 0];
        for (GLsizei i = 0; b && i < count; ++i) {
            const double w = 2 * b[i].rect[2] * t[0] * 0.5 * viewport[2];
            const double h = 2 * b[i].rect[3] * t[1] * 0.5 * viewport[3];
            const double side = fmax(fabs(w), fabs(h)) + 2.0;
            pixels += side * side;
        }
        primitives = count;
        add(kBlockPoints, 1, primitives, pixels);
    }
    addPixels(pixels);
    if (dumping())
        fprintf(stderr, "frame %d: program %d arrays mode %u count %d -> %.0f prims, %.0f px%s\n",
                frame, ordinal(), mode, count, primitives, pixels, blend ? " blended" : "");
}

void glDrawArrays(GLenum mode, GLint first, GLsizei count) {
    sceneArrays(mode, first, count);
    if (dropped(ordinal(), mode == GL_LINES ? "lines" : mode == GL_TRIANGLES ? "tris" : "points"))
        return;
    NEXT(glDrawArrays)(mode, first, count);
}

void glDrawArraysInstanced(GLenum mode, GLint first, GLsizei count, GLsizei instances) {
    // The block quads: the instance buffer is the one bound last to GL_ARRAY_BUFFER.
    const Shadow* s = arrayBuffer < kMaxIds ? &buffers[arrayBuffer] : NULL;
    const BlockInstance* b = s && s->data ? (const BlockInstance*)s->data : NULL;
    const int o = ordinal();
    const float* t = transform[o < kMaxPrograms ? o : 0];
    double pixels = 0.0;
    for (GLsizei i = 0; b && i < instances; ++i) {
        const double w = 2 * b[i].rect[2] * t[0] * 0.5 * viewport[2];
        const double h = 2 * b[i].rect[3] * t[1] * 0.5 * viewport[3];
        pixels += (fabs(w) + 2.0) * (fabs(h) + 2.0);
    }
    add(kBlockQuads, 1, (double)instances * (count - 2), pixels);
    addPixels(pixels);
    if (dumping())
        fprintf(stderr, "frame %d: program %d instanced %d x %d -> %.0f px%s\n", frame, ordinal(),
                count, instances, pixels, blend ? " blended" : "");
    if (dropped(ordinal(), NULL)) return;
    NEXT(glDrawArraysInstanced)(mode, first, count, instances);
}

// ImGui's vertices.
typedef struct {
    float x, y, u, v;
    unsigned col;
} UiVertex;

static void uiElements(GLsizei count, GLenum type, const void* indices, GLint baseVertex) {
    const Shadow* vs = arrayBuffer < kMaxIds ? &buffers[arrayBuffer] : NULL;
    const Shadow* is = elementBuffer < kMaxIds ? &buffers[elementBuffer] : NULL;
    if (!vs || !is || !vs->data || !is->data || type != GL_UNSIGNED_SHORT) {
        add(kUiOther, 1, count / 3, 0);
        return;
    }
    const unsigned short* idx = (const unsigned short*)(is->data + (size_t)indices);
    const UiVertex* v = (const UiVertex*)vs->data + baseVertex;
    double by[kTallies] = {0}, prims[kTallies] = {0};
    for (GLsizei k = 0; k + 2 < count; k += 3) {
        const UiVertex* t[3] = {&v[idx[k]], &v[idx[k + 1]], &v[idx[k + 2]]};
        double px[3], py[3];
        for (int j = 0; j < 3; ++j) toPixels(t[j]->x, t[j]->y, &px[j], &py[j]);
        const double area =
            triangleArea(px[0], py[0], px[1], py[1], px[2], py[2]) *
            scissorShare(fmin(px[0], fmin(px[1], px[2])), fmin(py[0], fmin(py[1], py[2])),
                         fmax(px[0], fmax(px[1], px[2])), fmax(py[0], fmax(py[1], py[2])));
        const int sameUv =
            t[0]->u == t[1]->u && t[1]->u == t[2]->u && t[0]->v == t[1]->v && t[1]->v == t[2]->v;
        int zero = 0, full = 0;
        for (int j = 0; j < 3; ++j) {
            const unsigned a = t[j]->col >> 24;
            zero += a == 0;
            full += a == 255;
        }
        const int what = !sameUv                ? kUiGlyph
                         : zero > 0 && zero < 3 ? kUiFeather
                         : full == 3            ? kUiSolidOpaque
                                                : kUiSolidTranslucent;
        by[what] += area;
        prims[what] += 1;
    }
    double pixels = 0.0;
    for (int w = 0; w < kTallies; ++w) {
        if (prims[w] == 0) continue;
        add(w, 0, prims[w], by[w]);
        pixels += by[w];
    }
    add(kUiOther, 1, 0, 0); // the call itself
    addPixels(pixels);
    if (dumping())
        fprintf(stderr,
                "frame %d: program %d elements %d tris (glyph %.0f/%.0fpx opaque %.0f/%.0fpx "
                "transl %.0f/%.0fpx feather %.0f/%.0fpx) scissor %dx%d%s\n",
                frame, ordinal(), count / 3, prims[kUiGlyph], by[kUiGlyph], prims[kUiSolidOpaque],
                by[kUiSolidOpaque], prims[kUiSolidTranslucent], by[kUiSolidTranslucent],
                prims[kUiFeather], by[kUiFeather], scissor[2], scissor[3], blend ? " blended" : "");
}

void glDrawElementsBaseVertex(GLenum mode, GLsizei count, GLenum type, const void* indices,
                              GLint baseVertex) {
    uiElements(count, type, indices, baseVertex);
    if (dropped(ordinal(), NULL)) return;
    // GLC_BREAK_RECTS=1 (an experiment): every draw's first triangle drawn on its own, so that no
    // draw's index count is a multiple of 6 (llvmpipe then never pairs triangles into rectangles).
    static int breakRects = -1;
    if (breakRects < 0) breakRects = getenv("GLC_BREAK_RECTS") != NULL;
    if (breakRects && count % 6 == 0 && count > 3 && type == GL_UNSIGNED_SHORT) {
        NEXT(glDrawElementsBaseVertex)(mode, 3, type, indices, baseVertex);
        NEXT(glDrawElementsBaseVertex)(mode, count - 3, type, (const char*)indices + 6, baseVertex);
        return;
    }
    NEXT(glDrawElementsBaseVertex)(mode, count, type, indices, baseVertex);
}

void glDrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
    uiElements(count, type, indices, 0);
    NEXT(glDrawElements)(mode, count, type, indices);
}
