#include "ui_renderer_gl.h"

#include "embedded_shaders.h"
#include "gl_api.h"
#include "gl_shader.h"
#include "renderer.h"
#include "ui_draw_merge.h"
#include "ui_draw_runs.h"
#include "ui_frame_base.h"

#include <algorithm>
#if defined(__GLIBC__)
#include <malloc.h> // mallopt
#endif
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

#if !SANDBOX_GL_ES
// A solid run smaller than this is drawn with the texture instead: on llvmpipe a draw call with
// a program switch costs about as much as sampling the texture for this many pixels.
constexpr float kMinSolidRunPixels = 4096.0f;
#endif

struct UiProgram {
    GLuint program = 0;
    GLint transform = -1;
    float transformSet[4] = {0.0f, 0.0f, 0.0f, 0.0f}; // the transform last given (WebGL: kept)
};

struct UiRenderer {
    UiProgram solid;
    UiProgram textured;
    GLuint vao = 0;
    GLuint vertexBuffer = 0;
    GLuint indexBuffer = 0;
    GLuint fontTexture = 0;
    bool fontsChanged = true;
    std::vector<UiDrawRun> runs;
    std::vector<ImDrawVert> vertices;   // GL ES: every list's, uploaded at once
    std::vector<std::uint32_t> indices; // GL ES: every list's, into all the vertices
    UiDrawMerger merger;                // GL ES: the draws of the commands
};
UiRenderer gUi;

GLuint textureName(ImTextureID id) {
    return static_cast<GLuint>(reinterpret_cast<std::intptr_t>(id));
}

bool buildUiProgram(UiProgram& p, const char* defines, std::string* error) {
    p.program =
        buildProgram(embedded_shaders::ui_vert, embedded_shaders::ui_frag, "ui", error, defines);
    if (!p.program) return false;
    p.transform = glGetUniformLocation(p.program, "uTransform");
    return true;
}

// The font atlas, sampled with the nearest texel: its glyphs are baked at their screen size.
void uploadFontTexture() {
    ImGuiIO& io = ImGui::GetIO();
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    if (!gUi.fontTexture) glGenTextures(1, &gUi.fontTexture);
    glBindTexture(GL_TEXTURE_2D, gUi.fontTexture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glBindTexture(GL_TEXTURE_2D, 0);
    io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(gUi.fontTexture)));
    gUi.fontsChanged = false;
}

// Blending as ImGui expects (premultiplied only in the alpha channel), no depth or culling,
// and ImGui's orthographic view: clip = (px - DisplayPos) mapped onto [-1, 1], y up.
void setupRenderState(const ImDrawData* data, int framebufferWidth, int framebufferHeight) {
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_CULL_FACE);
#if !SANDBOX_GL_ES // in the browser nothing turns them on (WebGL starts with both off)
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
#endif
    glEnable(GL_SCISSOR_TEST);
    glViewport(0, 0, framebufferWidth, framebufferHeight);
    const float l = data->DisplayPos.x, r = data->DisplayPos.x + data->DisplaySize.x;
    const float t = data->DisplayPos.y, b = data->DisplayPos.y + data->DisplaySize.y;
    const float transform[4] = {2.0f / (r - l), 2.0f / (t - b), (r + l) / (l - r),
                                (t + b) / (b - t)};
#if SANDBOX_GL_ES
    // WebGL draws with the textured program only (renderForWebGl), and a program keeps its
    // uniforms: the transform is given again only when the display changed (each GL call is a
    // call out to JavaScript there).
    UiProgram& p = gUi.textured;
    glUseProgram(p.program);
    if (!std::equal(transform, transform + 4, p.transformSet)) {
        glUniform4f(p.transform, transform[0], transform[1], transform[2], transform[3]);
        std::copy(transform, transform + 4, p.transformSet);
    }
#else
    for (const UiProgram* p : {&gUi.solid, &gUi.textured}) {
        glUseProgram(p->program);
        glUniform4f(p->transform, transform[0], transform[1], transform[2], transform[3]);
    }
#endif
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(gUi.vao);
    glBindBuffer(GL_ARRAY_BUFFER, gUi.vertexBuffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gUi.indexBuffer);
}

// The vertex attributes read ImGui's vertices (the VAO and the vertex buffer bound).
void pointAttributes() {
    const auto stride = static_cast<GLsizei>(sizeof(ImDrawVert));
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offsetof(ImDrawVert, pos)));
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offsetof(ImDrawVert, uv)));
    glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                          reinterpret_cast<void*>(offsetof(ImDrawVert, col)));
}

} // namespace

bool uiRendererInit(std::string* error) {
#if !SANDBOX_GL_ES && defined(__GLIBC__)
    // Every frame's uploads (glBufferData: new storage each time, megabytes at 1080p) are freed
    // and allocated again; by default glibc gives the freed memory back to the system and the
    // next frame faults it in again page by page (measured: up to a thousand page faults a frame
    // in a lesson's scene at 1080p, milliseconds of CPU). Up to 64 MB freed is kept, and blocks
    // up to 32 MB come from the heap rather than being mapped and unmapped each time. Unless the
    // environment sets glibc's malloc itself (GLIBC_TUNABLES=glibc.malloc....): those win (the
    // memory tests pin the mmap threshold to measure what the program holds, not what is kept).
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    if (!tunables || !std::strstr(tunables, "glibc.malloc.")) {
        mallopt(M_TRIM_THRESHOLD, 64 << 20);
        mallopt(M_MMAP_THRESHOLD, 32 << 20);
    }
#endif
    // WebGL draws every run textured (renderForWebGl): the solid program is not made there, one
    // program less to compile before the first frame.
#if SANDBOX_GL_ES
    const bool solid = true;
#else
    const bool solid = buildUiProgram(gUi.solid, "", error);
#endif
    if (!solid || !buildUiProgram(gUi.textured, "#define TEXTURED\n", error)) {
        uiRendererShutdown();
        return false;
    }
    glUseProgram(gUi.textured.program);
    glUniform1i(glGetUniformLocation(gUi.textured.program, "uTexture"), 0);
    glGenVertexArrays(1, &gUi.vao);
    glGenBuffers(1, &gUi.vertexBuffer);
    glGenBuffers(1, &gUi.indexBuffer);
    glBindVertexArray(gUi.vao);
    glBindBuffer(GL_ARRAY_BUFFER, gUi.vertexBuffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gUi.indexBuffer);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glEnableVertexAttribArray(2);
    pointAttributes();
    glBindVertexArray(0);
    ImGuiIO& io = ImGui::GetIO();
    io.BackendRendererName = "sandbox_gl33";
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset; // base vertex, or added
    gUi.fontsChanged = true;
    return true;
}

void uiRendererShutdown() {
    if (gUi.fontTexture) glDeleteTextures(1, &gUi.fontTexture);
    if (gUi.vertexBuffer) glDeleteBuffers(1, &gUi.vertexBuffer);
    if (gUi.indexBuffer) glDeleteBuffers(1, &gUi.indexBuffer);
    if (gUi.vao) glDeleteVertexArrays(1, &gUi.vao);
    if (gUi.solid.program) glDeleteProgram(gUi.solid.program);
    if (gUi.textured.program) glDeleteProgram(gUi.textured.program);
    gUi = UiRenderer{};
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->SetTexID(ImTextureID{});
    io.BackendRendererName = nullptr;
    io.BackendFlags &= ~ImGuiBackendFlags_RendererHasVtxOffset;
}

void uiRendererFontsChanged() {
    gUi.fontsChanged = true;
}

void uiRendererNewFrame() {
    if (gUi.fontsChanged && gUi.textured.program) uploadFontTexture();
}

namespace {

// A GL scissor box: x, y (GL's y goes up), width, height.
struct ScissorBox {
    GLint x = 0, y = 0;
    GLsizei width = 0, height = 0;
};

// The scissor box for a command: its clip rectangle in framebuffer pixels. False when nothing
// of it is visible.
bool clipBox(const ImDrawCmd& cmd, const ImDrawData* data, int fbHeight, ScissorBox* box) {
    const ImVec2 clipOffset = data->DisplayPos, clipScale = data->FramebufferScale;
    const float x0 = (cmd.ClipRect.x - clipOffset.x) * clipScale.x;
    const float y0 = (cmd.ClipRect.y - clipOffset.y) * clipScale.y;
    const float x1 = (cmd.ClipRect.z - clipOffset.x) * clipScale.x;
    const float y1 = (cmd.ClipRect.w - clipOffset.y) * clipScale.y;
    if (x1 <= x0 || y1 <= y0) return false;
    *box = ScissorBox{static_cast<GLint>(x0), static_cast<GLint>(fbHeight - y1),
                      static_cast<GLsizei>(x1 - x0), static_cast<GLsizei>(y1 - y0)};
    return true;
}

#if !SANDBOX_GL_ES // (WebGL: ui_draw_merge.h picks the boxes)
// The same, set as GL's scissor box.
bool scissorTo(const ImDrawCmd& cmd, const ImDrawData* data, int fbHeight, ScissorBox* box) {
    ScissorBox b;
    if (!clipBox(cmd, data, fbHeight, &b)) return false;
    glScissor(b.x, b.y, b.width, b.height);
    if (box) *box = b;
    return true;
}
#endif

// A command's own callback, or ImGui's request to set the render state again.
void runCallback(const ImDrawList* list, const ImDrawCmd& cmd, const ImDrawData* data, int fbWidth,
                 int fbHeight) {
    if (cmd.UserCallback == ImDrawCallback_ResetRenderState)
        setupRenderState(data, fbWidth, fbHeight);
    else
        cmd.UserCallback(list, &cmd);
}

} // namespace

#if SANDBOX_GL_ES
namespace {

// The browser's WebGL 2 (GL ES): every call crosses from wasm to JavaScript and on to the GPU
// process, which costs more than it saves to skip texturing, and a GPU rasterises anyway. So
// every list's vertices are uploaded at once, with the indices as 32-bit numbers into all of them
// (WebGL 2 has no glDrawElementsBaseVertex: the base vertex is added here, so the attributes
// never move), and the commands are drawn with the textured program (solid shapes sample the
// atlas's white texel: the same colours), neighbours that their scissor boxes do not clip as one
// draw (ui_draw_merge.h), each scissor box and texture set only when it changes.
void renderForWebGl(const ImDrawData* data, int fbWidth, int fbHeight) {
    gUi.vertices.clear();
    gUi.indices.resize(static_cast<std::size_t>(data->TotalIdxCount));
    gUi.merger.clear();
    const ImVec2 origin = data->DisplayPos, scale = data->FramebufferScale;
    std::size_t listIndices = 0; // where the list starts in the index buffer
    for (int n = 0; n < data->CmdListsCount; ++n) {
        const ImDrawList* list = data->CmdLists[n];
        const auto listVertices = static_cast<std::uint32_t>(gUi.vertices.size());
        gUi.vertices.insert(gUi.vertices.end(), list->VtxBuffer.begin(), list->VtxBuffer.end());
        for (const ImDrawCmd& cmd : list->CmdBuffer) {
            if (cmd.UserCallback) {
                gUi.merger.addCallback(list, &cmd);
                continue;
            }
            const std::uint32_t base = listVertices + cmd.VtxOffset;
            const ImDrawIdx* from = list->IdxBuffer.Data + cmd.IdxOffset;
            std::uint32_t* to = gUi.indices.data() + listIndices + cmd.IdxOffset;
            // Its triangles' reach (ImGui's units), the indices rebased on the way.
            const ImDrawVert* v = list->VtxBuffer.Data + cmd.VtxOffset;
            float x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
            float sum = 0.0f; // not finite when a vertex is not (NaN passes min and max by)
            for (unsigned k = 0; k < cmd.ElemCount; ++k) {
                to[k] = base + from[k];
                const ImVec2 p = v[from[k]].pos;
                x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
                y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
                sum += p.x + p.y;
            }
            if (!std::isfinite(sum)) x0 = y0 = -INFINITY, x1 = y1 = INFINITY; // clipped
            ScissorBox box;
            if (cmd.ElemCount == 0 || !clipBox(cmd, data, fbHeight, &box)) continue;
            const UiReach reach{(x0 - origin.x) * scale.x, fbHeight - (y1 - origin.y) * scale.y,
                                (x1 - origin.x) * scale.x, fbHeight - (y0 - origin.y) * scale.y};
            gUi.merger.add(listIndices + cmd.IdxOffset, cmd.ElemCount, cmd.GetTexID(),
                           {box.x, box.y, box.width, box.height}, reach);
        }
        listIndices += static_cast<std::size_t>(list->IdxBuffer.Size);
    }
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(gUi.vertices.size() * sizeof(ImDrawVert)),
                 gUi.vertices.data(), GL_STREAM_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(gUi.indices.size() * sizeof(std::uint32_t)),
                 gUi.indices.data(), GL_STREAM_DRAW);
    GLuint texture = ~0u; // the texture bound
    bool boxSet = false;  // the scissor box is `box`
    UiScissor box;
    for (const UiMergedDraw& d : gUi.merger.draws()) {
        if (d.callback) {
            runCallback(d.list, *d.callback, data, fbWidth, fbHeight);
            glUseProgram(gUi.textured.program);
            texture = ~0u;
            boxSet = false;
            continue;
        }
        if (!boxSet || !(d.box == box)) {
            glScissor(d.box.x, d.box.y, d.box.width, d.box.height);
            box = d.box;
            boxSet = true;
        }
        if (textureName(d.texture) != texture) {
            texture = textureName(d.texture);
            glBindTexture(GL_TEXTURE_2D, texture);
        }
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(d.count), GL_UNSIGNED_INT,
                       reinterpret_cast<void*>(d.first * sizeof(std::uint32_t)));
    }
    glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(0);
}

} // namespace
#else
namespace {

// An opaque fill of at least this many sure pixels is cleared there rather than rasterised: on
// llvmpipe a scissored clear is an unblended quad Mesa draws, cheaper than the fill's blended
// triangles (a blended pixel 2 to 3.5 ns).
constexpr int kMinClearedPixels = 4096;

// A command's runs (ui_draw_runs.h): the font atlas's split into solid and textured runs and
// opaque fills; any other texture's, one run.
void commandRuns(const ImDrawList* list, const ImDrawCmd& cmd, const ImDrawData* data,
                 std::vector<UiDrawRun>& runs) {
    runs.clear();
    if (textureName(cmd.GetTexID()) != gUi.fontTexture) {
        runs.push_back({cmd.IdxOffset, cmd.ElemCount, false, {}, 0});
        return;
    }
    const ImDrawVert* vertices = list->VtxBuffer.Data + cmd.VtxOffset;
    const ImDrawIdx* indices = list->IdxBuffer.Data + cmd.IdxOffset;
    splitIntoRuns(vertices, indices, cmd.IdxOffset, cmd.ElemCount,
                  ImGui::GetIO().Fonts->TexUvWhitePixel, kMinSolidRunPixels, runs);
    findOpaqueFills(vertices, indices, cmd.IdxOffset, data->DisplayPos, data->FramebufferScale,
                    kMinClearedPixels, runs);
}

// The framebuffer pixels (a box in GL's rows, y up) that the `count` indexed triangles can
// touch: a pixel is drawn only where its centre is inside a triangle, so inside the box of their
// vertices; a 32nd of a pixel more on every side (GL's float transform and Mesa's 1/256 px
// snapping move a vertex far less). Everything when a vertex is not finite.
ScissorBox trianglesReach(const ImDrawVert* vertices, const ImDrawIdx* indices, unsigned count,
                          const ImDrawData* data, int fbWidth, int fbHeight) {
    const ScissorBox everywhere{-1, -1, fbWidth + 2, fbHeight + 2};
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (unsigned k = 0; k < count; ++k) {
        const ImVec2 p = vertices[indices[k]].pos;
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return everywhere;
        x0 = std::min(x0, double(p.x)), x1 = std::max(x1, double(p.x));
        y0 = std::min(y0, double(p.y)), y1 = std::max(y1, double(p.y));
    }
    if (!(x0 <= x1)) return {}; // no triangle
    const ImVec2 origin = data->DisplayPos, scale = data->FramebufferScale;
    constexpr double kSlack = 1.0 / 32.0;
    // The first and last pixel (column, or row from the top) whose centre is within [a, b] (in
    // framebuffer pixels), clamped to a pixel beyond the framebuffer.
    const auto first = [&](double a, int size) {
        return static_cast<int>(std::ceil(std::clamp(a - 0.5 - kSlack, -2.0, size + 2.0)));
    };
    const auto last = [&](double b, int size) {
        return static_cast<int>(std::floor(std::clamp(b - 0.5 + kSlack, -2.0, size + 2.0)));
    };
    const int c0 = first((x0 - origin.x) * scale.x, fbWidth);
    const int c1 = last((x1 - origin.x) * scale.x, fbWidth);
    const int r0 = first((y0 - origin.y) * scale.y, fbHeight);
    const int r1 = last((y1 - origin.y) * scale.y, fbHeight);
    if (c1 < c0 || r1 < r0) return {}; // no pixel centre inside
    return {c0, fbHeight - 1 - r1, c1 - c0 + 1, r1 - r0 + 1};
}

bool overlaps(const ScissorBox& a, const ScissorBox& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
           b.y < a.y + a.height;
}

// An opaque fill (findOpaqueFills): its sure pixels within `scissor` cleared to its colour (the
// colour its triangles give them: one colour, alpha 255, blended over anything), then its
// triangles `draw`n under the scissor's bands around them (the fill's rounded corners and
// anti-aliased-free edges), in those bands only that its triangles reach (`reach`,
// trianglesReach: a band they do not reach would get no pixel from them, and each draw costs the
// main thread Mesa's set-up of every triangle); the command's scissor set again after.
template <class Draw>
void drawOpaqueFill(const UiDrawRun& run, const ScissorBox& scissor, const ScissorBox& reach,
                    int fbHeight, Draw draw, bool clear = true) {
    // The sure pixels in GL's rows (y up), clipped to the scissor.
    const GLint sx1 = scissor.x + scissor.width, sy1 = scissor.y + scissor.height;
    const GLint x0 = std::max(scissor.x, run.inside.x0), x1 = std::min(sx1, run.inside.x1);
    const GLint y0 = std::max(scissor.y, fbHeight - run.inside.y1);
    const GLint y1 = std::min(sy1, fbHeight - run.inside.y0);
    if (x1 <= x0 || y1 <= y0) {
        draw();
        return;
    }
    if (clear) { // else the frame's base left its colour there (uiRendererPlanFrameBase)
        const ImU32 c = run.color;
        glClearColor(static_cast<float>(c >> IM_COL32_R_SHIFT & 0xFF) / 255.0f,
                     static_cast<float>(c >> IM_COL32_G_SHIFT & 0xFF) / 255.0f,
                     static_cast<float>(c >> IM_COL32_B_SHIFT & 0xFF) / 255.0f, 1.0f);
        glScissor(x0, y0, x1 - x0, y1 - y0);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    const ScissorBox bands[4] = {{scissor.x, y1, scissor.width, sy1 - y1},              // above
                                 {scissor.x, scissor.y, scissor.width, y0 - scissor.y}, // below
                                 {scissor.x, y0, x0 - scissor.x, y1 - y0},              // left
                                 {x1, y0, sx1 - x1, y1 - y0}};                          // right
    for (const ScissorBox& b : bands) {
        if (b.width <= 0 || b.height <= 0 || !overlaps(b, reach)) continue;
        glScissor(b.x, b.y, b.width, b.height);
        draw();
    }
    glScissor(scissor.x, scissor.y, scissor.width, scissor.height);
}

} // namespace
#endif

namespace {

// ImGui's buffers keep their capacity (ImVector's assignment frees it first).
template <typename T> void copyInto(ImVector<T>& to, const ImVector<T>& from) {
    to.resize(from.Size);
    if (from.Size > 0)
        std::memcpy(to.Data, from.Data, static_cast<std::size_t>(from.Size) * sizeof(T));
}

} // namespace

void uiRendererCapture(UiFrame& frame, bool copy) {
    frame.prepared = frame.planned = false;
    const ImDrawData* data = ImGui::GetDrawData();
    if (!copy || !data) {
        frame.data = data;
        return;
    }
    const std::size_t count = static_cast<std::size_t>(std::max(data->CmdListsCount, 0));
    while (frame.lists.size() < count)
        frame.lists.push_back(std::make_unique<ImDrawList>(ImGui::GetDrawListSharedData()));
    frame.listPointers.resize(count);
    for (std::size_t n = 0; n < count; ++n) {
        const ImDrawList& from = *data->CmdLists[n];
        ImDrawList& to = *frame.lists[n];
        copyInto(to.CmdBuffer, from.CmdBuffer);
        copyInto(to.IdxBuffer, from.IdxBuffer);
        copyInto(to.VtxBuffer, from.VtxBuffer);
        to.Flags = from.Flags;
        frame.listPointers[n] = &to;
    }
    frame.copy = *data;
    frame.copy.CmdLists = frame.listPointers.data();
    frame.data = &frame.copy;
}

void uiRendererRender(const UiFrame& frame) {
    const ImDrawData* data = frame.data;
    if (!data) return;
    const int fbWidth = static_cast<int>(data->DisplaySize.x * data->FramebufferScale.x);
    const int fbHeight = static_cast<int>(data->DisplaySize.y * data->FramebufferScale.y);
    if (fbWidth <= 0 || fbHeight <= 0 || !gUi.textured.program) return;
    setupRenderState(data, fbWidth, fbHeight);
#if SANDBOX_GL_ES
    renderForWebGl(data, fbWidth, fbHeight);
#else
    const GLenum indexType = sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT;
    GLuint current = 0; // the program in use
    const bool planned = frame.planned, prepared = frame.prepared;
    std::size_t drawnCmd = 0; // the commands drawn so far (the plan's order)
    std::size_t fill = 0;     // the fills met so far (the plan's order)
    for (int n = 0; n < data->CmdListsCount; ++n) {
        const ImDrawList* list = data->CmdLists[n];
        glBufferData(GL_ARRAY_BUFFER,
                     static_cast<GLsizeiptr>(list->VtxBuffer.Size) * sizeof(ImDrawVert),
                     list->VtxBuffer.Data, GL_STREAM_DRAW);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                     static_cast<GLsizeiptr>(list->IdxBuffer.Size) * sizeof(ImDrawIdx),
                     list->IdxBuffer.Data, GL_STREAM_DRAW);
        for (const ImDrawCmd& cmd : list->CmdBuffer) {
            if (cmd.UserCallback) {
                runCallback(list, cmd, data, fbWidth, fbHeight);
                current = 0;
                continue;
            }
            ScissorBox scissor;
            if (!scissorTo(cmd, data, fbHeight, &scissor)) continue;
            glBindTexture(GL_TEXTURE_2D, textureName(cmd.GetTexID()));

            const UiDrawRun *runs = nullptr, *runsEnd = nullptr;
            if (prepared && drawnCmd < frame.planCmdEnd.size()) { // as the plan worked them out
                runs = frame.planRuns.data() + (drawnCmd ? frame.planCmdEnd[drawnCmd - 1] : 0);
                runsEnd = frame.planRuns.data() + frame.planCmdEnd[drawnCmd];
            } else {
                commandRuns(list, cmd, data, gUi.runs);
                runs = gUi.runs.data();
                runsEnd = runs + gUi.runs.size();
            }
            ++drawnCmd;
            for (; runs != runsEnd; ++runs) {
                const UiDrawRun& run = *runs;
                const GLuint program = run.solid ? gUi.solid.program : gUi.textured.program;
                if (program != current) glUseProgram(program);
                current = program;
                const auto* firstIndex = reinterpret_cast<void*>(
                    static_cast<std::size_t>(run.firstIndex) * sizeof(ImDrawIdx));
                const auto draw = [&] {
                    glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(run.indexCount),
                                             indexType, firstIndex,
                                             static_cast<GLint>(cmd.VtxOffset));
                };
                if (run.inside.empty()) {
                    draw();
                } else {
                    const bool skip =
                        planned && fill < frame.fillSkipped.size() && frame.fillSkipped[fill];
                    ++fill;
                    const ScissorBox reach = trianglesReach(
                        list->VtxBuffer.Data + cmd.VtxOffset, list->IdxBuffer.Data + run.firstIndex,
                        run.indexCount, data, fbWidth, fbHeight);
                    drawOpaqueFill(run, scissor, reach, fbHeight, draw, !skip);
                }
            }
        }
    }
    glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(0);
#endif
}

#if !SANDBOX_GL_ES
namespace {

UiPixelRect clipRect(const UiPixelRect& a, const UiPixelRect& b) {
    return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

// What each draw of `data` paints (UiPaint), in the order uiRendererRender draws them, with the
// same runs; `fillPaint` gets, for each opaque fill run, its paint's index.
void listPaints(UiFrame& frame, int fbWidth, int fbHeight, std::vector<std::size_t>& fillPaint) {
    const ImDrawData* data = frame.data;
    std::vector<UiPaint>& paints = frame.paints;
    const ImVec2 origin = data->DisplayPos, scale = data->FramebufferScale;
    const UiPixelRect everywhere{0, 0, fbWidth, fbHeight};
    for (int n = 0; n < data->CmdListsCount; ++n) {
        const ImDrawList* list = data->CmdLists[n];
        for (const ImDrawCmd& cmd : list->CmdBuffer) {
            if (cmd.UserCallback) { // draws who knows what
                paints.push_back({everywhere, {}, 0});
                continue;
            }
            ScissorBox box;
            if (!clipBox(cmd, data, fbHeight, &box)) continue;
            const UiPixelRect clip{box.x, fbHeight - (box.y + box.height), box.x + box.width,
                                   fbHeight - box.y};
            const ImDrawVert* vertices = list->VtxBuffer.Data + cmd.VtxOffset;
            commandRuns(list, cmd, data, frame.runs);
            frame.planRuns.insert(frame.planRuns.end(), frame.runs.begin(), frame.runs.end());
            frame.planCmdEnd.push_back(frame.planRuns.size());
            for (const UiDrawRun& run : frame.runs) {
                float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
                const ImDrawIdx* idx = list->IdxBuffer.Data + run.firstIndex;
                for (unsigned k = 0; k < run.indexCount; ++k) {
                    const ImVec2 p = vertices[idx[k]].pos;
                    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
                    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
                }
                UiPaint paint;
                // A pixel more on every side: surely all it touches. Clamped to the clip (and a
                // pixel beyond) before becoming whole numbers: a vertex far off screen (a line
                // to a block at 1e9 m/s) must not overflow into an empty box; NaN: everywhere.
                const auto px = [](float v, int lo, int hi, bool up) {
                    if (!(v == v)) return up ? hi : lo;
                    const double c =
                        std::clamp(static_cast<double>(up ? std::ceil(v) : std::floor(v)),
                                   static_cast<double>(lo), static_cast<double>(hi));
                    return static_cast<int>(c) + (up ? 1 : -1);
                };
                if (x0 <= x1 && y0 <= y1)
                    paint.bounds = clipRect(
                        clip, {px((x0 - origin.x) * scale.x, clip.x0 - 1, clip.x1 + 1, false),
                               px((y0 - origin.y) * scale.y, clip.y0 - 1, clip.y1 + 1, false),
                               px((x1 - origin.x) * scale.x, clip.x0 - 1, clip.x1 + 1, true),
                               px((y1 - origin.y) * scale.y, clip.y0 - 1, clip.y1 + 1, true)});
                else if (run.indexCount > 0) // no finite vertex: anywhere in the clip
                    paint.bounds = clip;
                if (!run.inside.empty()) {
                    fillPaint.push_back(paints.size());
                    paint.inside = clipRect(clip, run.inside);
                    paint.color = run.color;
                }
                paints.push_back(paint);
            }
        }
    }
}

float channel(ImU32 c, int shift) {
    return static_cast<float>(c >> shift & 0xFF) / 255.0f;
}

} // namespace

bool uiRendererPlansFrameBase() {
    return true;
}

FrameBase uiRendererPlanFrameBase(UiFrame& frame, int sceneWidth, int sceneHeight,
                                  const PixelBox& sceneDrawn, const PixelBox& arena) {
    FrameBase base;
    const ImDrawData* data = frame.data;
    frame.planned = frame.prepared = false;
    if (!data || !gUi.textured.program) return base;
    const int fbWidth = static_cast<int>(data->DisplaySize.x * data->FramebufferScale.x);
    const int fbHeight = static_cast<int>(data->DisplaySize.y * data->FramebufferScale.y);
    // The UI's framebuffer is the scene's (a window being resized may give them apart for a
    // frame: then no plan, the frame drawn as before).
    if (fbWidth <= 0 || fbHeight <= 0 || fbWidth != sceneWidth || fbHeight != sceneHeight)
        return base;
    frame.paints.clear();
    frame.planRuns.clear();
    frame.planCmdEnd.clear();
    std::vector<std::size_t> fillPaint;
    listPaints(frame, fbWidth, fbHeight, fillPaint);
    frame.prepared = true;
    const UiFrameBase plan =
        planFrameBase(frame.paints, {sceneDrawn.x0, sceneDrawn.y0, sceneDrawn.x1, sceneDrawn.y1},
                      {arena.x0, arena.y0, arena.x1, arena.y1}, fbWidth, fbHeight);
    if (!plan.planned) return base;
    frame.planned = true;
    frame.fillSkipped.assign(fillPaint.size(), false);
    for (std::size_t f = 0; f < fillPaint.size(); ++f)
        frame.fillSkipped[f] = plan.skip[fillPaint[f]];
    base.planned = true;
    base.clearTo = plan.clearTo == UiFrameClear::Fills   ? FrameBase::Clear::Colour
                   : plan.clearTo == UiFrameClear::Arena ? FrameBase::Clear::Arena
                                                         : FrameBase::Clear::Background;
    base.clear[0] = channel(plan.clear, IM_COL32_R_SHIFT);
    base.clear[1] = channel(plan.clear, IM_COL32_G_SHIFT);
    base.clear[2] = channel(plan.clear, IM_COL32_B_SHIFT);
    base.clear[3] = 1.0f;
    for (const UiPixelRect& r : plan.background)
        base.background.push_back({r.x0, r.y0, r.x1, r.y1});
    for (const UiPixelRect& r : plan.arena) base.arena.push_back({r.x0, r.y0, r.x1, r.y1});
    return base;
}
#else
bool uiRendererPlansFrameBase() {
    return false; // WebGL: a GPU pays little for a fill
}

FrameBase uiRendererPlanFrameBase(UiFrame&, int, int, const PixelBox&, const PixelBox&) {
    return {};
}
#endif
