#include "offscreen_osmesa.h"

#include "gl_api.h"
#include "ui_renderer_gl.h"

#include <GL/osmesa.h>

#include <imgui.h>

#include <cfloat>
#include <cstring>
#include <utility>

bool offscreenInit(OffscreenOsmesa& o, int width, int height, std::string* error) {
    // BGRA, a window's usual order, as the window's llvmpipe gets it: Mesa 22.3's llvmpipe keeps
    // its window-framebuffer paths (in Mesa's source: axis-aligned quads set up as rectangles,
    // no x/y clipping inside a guard band) for B8G8R8A8 without depth; the same pixels for a few
    // per cent less CPU a frame (docs/performance.md). The PNG's RGBA is made when the pixels are
    // read (offscreenPixelsTopDown).
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_BGRA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!ctx) {
        if (error) *error = "OSMesa cannot create an OpenGL 3.3 core context";
        return false;
    }
    o.width = width;
    o.height = height;
    o.buffer.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
    if (!OSMesaMakeCurrent(ctx, o.buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
        if (error) *error = "OSMesa cannot make the context current";
        OSMesaDestroyContext(ctx);
        return false;
    }
    o.context = ctx;
    std::string uiError;
    if (!uiRendererInit(&uiError)) {
        if (error) *error = "cannot start the ImGui renderer: " + uiError;
        offscreenShutdown(o);
        return false;
    }
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
    return true;
}

void offscreenShutdown(OffscreenOsmesa& o) {
    if (!o.context) return;
    uiRendererShutdown();
    OSMesaDestroyContext(static_cast<OSMesaContext>(o.context));
    o.context = nullptr;
}

void offscreenFrameInput(int width, int height, double deltaSeconds) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DeltaTime = static_cast<float>(deltaSeconds > 0.0 ? deltaSeconds : 1.0 / 60.0);
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
}

void offscreenNewFrame(OffscreenOsmesa& o, double deltaSeconds) {
    offscreenFrameInput(o.width, o.height, deltaSeconds);
    uiRendererNewFrame();
}

void offscreenFinish(OffscreenOsmesa&) {
    glFinish();
}

std::vector<std::uint8_t> offscreenPixelsTopDown(const OffscreenOsmesa& o) {
    const std::size_t row = static_cast<std::size_t>(o.width) * 4;
    std::vector<std::uint8_t> out(o.buffer.size());
    for (int y = 0; y < o.height; ++y) {
        const std::size_t src = static_cast<std::size_t>(o.height - 1 - y) * row;
        std::memcpy(out.data() + static_cast<std::size_t>(y) * row, o.buffer.data() + src, row);
    }
    for (std::size_t i = 0; i < out.size(); i += 4) {
        std::swap(out[i], out[i + 2]); // BGRA to RGBA
        out[i + 3] = 255;              // opaque PNGs
    }
    return out;
}

std::string offscreenGlDescription() {
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return std::string(version ? version : "?") + ", " + (renderer ? renderer : "?");
}
