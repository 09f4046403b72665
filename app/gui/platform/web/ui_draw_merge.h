// The browser's UI draws (WebGL 2, ui_renderer_gl.cpp's renderForWebGl): each of ImGui's draw
// commands is a draw under its own scissor box, and every WebGL call crosses from wasm to
// JavaScript and on to the GPU process. A command whose triangles lie inside its scissor box
// loses nothing to it, so the box may be any that holds them: such neighbours (one texture, their
// indices one after the other) become one draw under a box that holds them all, and so does a
// command that its box does clip with neighbours inside that same box. The same triangles in the
// same order under scissors that cut the same pixels: the same pixels. No GL here: tested in
// tests/app.
#pragma once

#include <imgui.h>

#include <cstddef>
#include <vector>

// A scissor box as GL takes it: framebuffer pixels, rows counted from the bottom.
struct UiScissor {
    int x = 0, y = 0, width = 0, height = 0;
    bool operator==(const UiScissor& o) const {
        return x == o.x && y == o.y && width == o.width && height == o.height;
    }
};

// Where a command's triangles reach: the bounding box of its vertices in framebuffer pixels
// (rows from the bottom, as UiScissor's). A pixel is drawn when its centre (a half pixel) is
// inside a triangle, so inside the box: when the box lies within a scissor box, that scissor
// box keeps every pixel.
struct UiReach {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool within(const UiScissor& s) const {
        return x0 >= static_cast<float>(s.x) && x1 <= static_cast<float>(s.x + s.width) &&
               y0 >= static_cast<float>(s.y) && y1 <= static_cast<float>(s.y + s.height);
    }
};

struct UiMergedDraw {
    std::size_t first = 0, count = 0; // indices, into the frame's one index buffer
    ImTextureID texture = nullptr;
    UiScissor box;
    // An ImGui callback command in its place (no draw): the draws around it never join.
    const ImDrawList* list = nullptr;
    const ImDrawCmd* callback = nullptr;
};

class UiDrawMerger {
  public:
    void clear();
    // A command of `count` indices from `first`, with its own scissor box and its triangles'
    // reach: joins the last draw when it can (the same texture, the indices next to its, and a
    // box that keeps every pixel of both as each one's own box does), else starts a draw.
    void add(std::size_t first, std::size_t count, ImTextureID texture, const UiScissor& box,
             const UiReach& reach);
    void addCallback(const ImDrawList* list, const ImDrawCmd* cmd);
    const std::vector<UiMergedDraw>& draws() const { return draws_; }

  private:
    std::vector<UiMergedDraw> draws_;
    // The last draw's: whether one of its commands is clipped by its box (then the box is that
    // one's own and stays), and the reach of those it does not clip (each pixel of theirs kept).
    bool fixed_ = false;
    UiReach reach_;
};
