#include "screen_text.h"

#include "dock_layout.h" // jsonString, jsonRect
#include "imgui_ext.h"

#include <imgui.h>

#include <climits>
#include <cmath>
#include <cstring>
#include <map>
#include <utility>

namespace {

// The parts of the screen by the name of what draws them (ImGui's name for a draw list: a
// window's title, "##Background" for the list the scene draws into); other windows keep their
// titles, a child window its parent's ("Controls/##scroll_1A2B" is "Controls").
struct TextRoleRow {
    const char* drawList;
    const char* role;
};
constexpr TextRoleRow kTextRoles[] = {
    {"##Background", "scene"},
    {"##Foreground", "scene"},
    {"Lesson caption", "caption"},
    {"##Tooltip", "tooltip"}, // a prefix: ImGui numbers them ("##Tooltip_00")
};

// A part of a draw list with a role of its own (TextRole), by vertex number.
struct RoleSpan {
    const ImDrawList* list;
    int from, to;
    const char* role;
};
std::vector<RoleSpan> gRoles;

// Parts of draw lists holding a text wider than its room (markTextOverflowing), by vertex number.
struct OverflowSpan {
    const ImDrawList* list;
    int from, to;
};
std::vector<OverflowSpan> gOverflows;

bool overflowing(const ImDrawList& list, int vertex) {
    for (const OverflowSpan& o : gOverflows)
        if (o.list == &list && vertex >= o.from && vertex < o.to) return true;
    return false;
}

std::string roleOf(const ImDrawList& list, int vertex) {
    for (auto it = gRoles.rbegin(); it != gRoles.rend(); ++it)
        if (it->list == &list && vertex >= it->from && vertex < it->to) return it->role;
    std::string name = imgui_ext::drawListOwner(list);
    for (const TextRoleRow& row : kTextRoles)
        if (name.rfind(row.drawList, 0) == 0) return row.role;
    const std::size_t slash = name.find('/');
    return slash == std::string::npos ? name : name.substr(0, slash);
}

struct GlyphRef {
    const ImFont* font = nullptr;
    const ImFontGlyph* glyph = nullptr;
};

// Every visible glyph of every font by the top-left corner of its atlas rectangle.
class GlyphIndex {
  public:
    explicit GlyphIndex(const ImFontAtlas& atlas) {
        for (const ImFont* font : atlas.Fonts)
            for (const ImFontGlyph& g : font->Glyphs)
                if (g.Visible) byCorner_.emplace(std::make_pair(g.U0, g.V0), GlyphRef{font, &g});
    }
    // The glyph whose atlas rectangle holds (u0, v0)-(u1, v1): itself, or cut by the clipping.
    GlyphRef find(float u0, float v0, float u1, float v1) const {
        const auto exact = byCorner_.find(std::make_pair(u0, v0));
        if (exact != byCorner_.end() && exact->second.glyph->U1 == u1 &&
            exact->second.glyph->V1 == v1)
            return exact->second;
        for (const auto& [corner, ref] : byCorner_) {
            const ImFontGlyph& g = *ref.glyph;
            if (u0 >= g.U0 && v0 >= g.V0 && u1 <= g.U1 && v1 <= g.V1 && u1 > u0 && v1 > v0)
                return ref;
        }
        return {};
    }

  private:
    std::map<std::pair<float, float>, GlyphRef> byCorner_;
};

// One glyph as drawn: where its pen stood and at what size.
struct DrawnGlyph {
    GlyphRef ref;
    double penX = 0.0, lineTop = 0.0, scale = 1.0;
    bool clipped = false;
    bool hidden = false; // wholly outside its clip rectangle: no pixel of it is drawn
};

// A rectangle drawn with the font's texture as a glyph, if it is one.
bool readGlyph(const imgui_ext::DrawnRect& r, const GlyphIndex& glyphs, DrawnGlyph& out) {
    const GlyphRef ref = glyphs.find(r.uvMin.x, r.uvMin.y, r.uvMax.x, r.uvMax.y);
    if (!ref.glyph) return false;
    const ImFontGlyph& g = *ref.glyph;
    const ImVec4& clip = r.clip;
    // The part of the glyph's atlas rectangle drawn, and so the whole glyph's size on screen.
    const double fu0 = (r.uvMin.x - g.U0) / double(g.U1 - g.U0),
                 fu1 = (r.uvMax.x - g.U0) / double(g.U1 - g.U0);
    const double fv0 = (r.uvMin.y - g.V0) / double(g.V1 - g.V0),
                 fv1 = (r.uvMax.y - g.V0) / double(g.V1 - g.V0);
    const double width = (r.max.x - r.min.x) / (fu1 - fu0);
    const double height = (r.max.y - r.min.y) / (fv1 - fv0);
    const double x0 = r.min.x - fu0 * width, y0 = r.min.y - fv0 * height;
    out.ref = ref;
    out.scale = g.X1 - g.X0 >= g.Y1 - g.Y0 ? width / (g.X1 - g.X0) : height / (g.Y1 - g.Y0);
    out.penX = x0 - g.X0 * out.scale;
    out.lineTop = y0 - g.Y0 * out.scale;
    constexpr double kSlack = 0.01; // px: float rounding
    out.clipped = fu0 > 1e-6 || fu1 < 1.0 - 1e-6 || fv0 > 1e-6 || fv1 < 1.0 - 1e-6 ||
                  x0 < clip.x - kSlack || y0 < clip.y - kSlack || x0 + width > clip.z + kSlack ||
                  y0 + height > clip.w + kSlack;
    out.hidden = r.max.x <= clip.x + kSlack || r.min.x >= clip.z - kSlack ||
                 r.max.y <= clip.y + kSlack || r.min.y >= clip.w - kSlack;
    return true;
}

void appendUtf8(std::string& s, unsigned c) {
    if (c < 0x80) {
        s += static_cast<char>(c);
    } else if (c < 0x800) {
        s += static_cast<char>(0xC0 | (c >> 6));
        s += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        s += static_cast<char>(0xE0 | (c >> 12));
        s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        s += static_cast<char>(0x80 | (c & 0x3F));
    }
}

// A text being read: glyphs of one font and size, on a line or on lines one under another.
struct Run {
    ScreenText out;
    const ImFont* font = nullptr;
    double scale = 1.0, startX = 0.0, lineTop = 0.0, penEnd = 0.0, right = 0.0;
    int lines = 0;
    int shown = 0; // glyphs with pixels drawn
    std::string role;
};

// How many spaces lie between the pen and `penX` on a text's line; -1: not a whole number.
int spacesBetween(double pen, double penX, double space) {
    constexpr double kSlack = 0.02; // px
    const double gap = penX - pen;
    if (gap < -kSlack || space <= 0.0) return -1;
    const double n = std::round(gap / space);
    return n <= 16 && std::fabs(gap - n * space) <= kSlack ? static_cast<int>(n) : -1;
}

bool continues(Run& run, const DrawnGlyph& g, const std::string& role) {
    if (!run.font || run.font != g.ref.font || std::fabs(run.scale - g.scale) > 1e-4 * run.scale ||
        run.role != role)
        return false;
    constexpr double kSlack = 0.02; // px
    const double space = run.font->GetCharAdvance(' ') * run.scale;
    const double lineHeight = run.font->FontSize * run.scale;
    int spaces = -1;
    if (std::fabs(g.lineTop - run.lineTop) <= kSlack) {
        spaces = spacesBetween(run.penEnd, g.penX, space);
    } else if (std::fabs(g.lineTop - (run.lineTop + lineHeight)) <= kSlack) {
        spaces = spacesBetween(run.startX, g.penX, space);
        if (spaces < 0) return false;
        run.out.text += '\n';
        run.lineTop = g.lineTop;
        ++run.lines;
    }
    if (spaces < 0) return false;
    run.out.text.append(static_cast<std::size_t>(spaces), ' ');
    return true;
}

void finish(Run& run, std::vector<ScreenText>& texts) {
    if (!run.font) return;
    if (run.shown == 0) { // wholly outside its window (scrolled away, a hidden row): not drawn
        run = Run{};
        return;
    }
    ScreenText& t = run.out;
    const double lineHeight = run.font->FontSize * run.scale;
    t.rect = {run.startX, run.lineTop - (run.lines - 1) * lineHeight, run.right - run.startX,
              run.lines * lineHeight};
    t.px = lineHeight;
    t.window = run.role;
    // A label's shadow: the same text drawn just before, a pixel or so off; listed once.
    if (!texts.empty()) {
        const ScreenText& prev = texts.back();
        if (prev.text == t.text && std::fabs(prev.px - t.px) < 0.01 &&
            std::fabs(prev.rect.x - t.rect.x) <= 1.5 && std::fabs(prev.rect.y - t.rect.y) <= 1.5 &&
            prev.window == t.window)
            texts.pop_back();
    }
    texts.push_back(t);
    run = Run{};
}

void readList(const ImDrawList& list, const ImTextureID fontTexture, const GlyphIndex& glyphs,
              std::vector<ScreenText>& texts) {
    Run run;
    // One text is drawn in one go: anything else drawn (a button's frame) or a new command ends
    // it.
    bool between = true;
    imgui_ext::forEachDrawnRect(
        list, fontTexture,
        [&](const imgui_ext::DrawnRect& r) {
            DrawnGlyph g;
            if (!readGlyph(r, glyphs, g)) {
                between = true;
                return;
            }
            const std::string role = roleOf(list, r.vertex);
            if (between || !continues(run, g, role)) {
                between = false;
                finish(run, texts);
                run.font = g.ref.font;
                run.scale = g.scale;
                run.startX = run.penEnd = run.right = g.penX;
                run.lineTop = g.lineTop;
                run.lines = 1;
                run.role = role;
            }
            appendUtf8(run.out.text, g.ref.glyph->Codepoint);
            run.out.clipped = run.out.clipped || g.clipped || overflowing(list, r.vertex);
            run.shown += g.hidden ? 0 : 1;
            run.penEnd = g.penX + g.ref.glyph->AdvanceX * g.scale;
            run.right = std::fmax(run.right, run.penEnd);
        },
        [&between] { between = true; });
    finish(run, texts);
}

double rounded(double v) {
    return std::round(v * 100.0) / 100.0; // to the hundredth of a pixel: float noise is off
}

} // namespace

std::vector<ScreenText> readScreenText(const ImDrawData& data, const ImFontAtlas& atlas) {
    const GlyphIndex glyphs(atlas);
    std::vector<ScreenText> texts;
    for (int i = 0; i < data.CmdListsCount; ++i)
        readList(*data.CmdLists[i], atlas.TexID, glyphs, texts);
    for (ScreenText& t : texts) {
        t.rect = {rounded(t.rect.x - data.DisplayPos.x), rounded(t.rect.y - data.DisplayPos.y),
                  rounded(t.rect.width), rounded(t.rect.height)};
        t.px = rounded(t.px);
    }
    return texts;
}

std::string screenTextJson(const std::vector<ScreenText>& texts) {
    std::string out = "{\"texts\": [";
    for (std::size_t i = 0; i < texts.size(); ++i) {
        const ScreenText& t = texts[i];
        char px[32];
        std::snprintf(px, sizeof px, "%.10g", t.px);
        out += (i ? ",\n  " : "\n  ") + std::string("{\"text\": ") + jsonString(t.text) +
               ", \"rect\": " + jsonRect(t.rect) + ", \"px\": " + px +
               ", \"window\": " + jsonString(t.window) +
               ", \"clipped\": " + (t.clipped ? "true" : "false") + "}";
    }
    return out + (texts.empty() ? "]}\n" : "\n]}\n");
}

TextRole::TextRole(ImDrawList* list, const char* role) : list_(list), outer_(role) {
    gRoles.push_back({list, imgui_ext::drawListVertices(*list), INT_MAX, role});
}

TextRole::~TextRole() {
    for (auto it = gRoles.rbegin(); it != gRoles.rend(); ++it)
        if (it->list == list_ && it->to == INT_MAX && it->role == outer_) {
            it->to = imgui_ext::drawListVertices(*list_);
            break;
        }
}

void markTextOverflowing(const ImDrawList* list, int from, int to) {
    gOverflows.push_back({list, from, to});
}

void forgetTextRoles() {
    gRoles.clear();
    gOverflows.clear();
}
