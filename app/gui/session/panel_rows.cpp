#include "panel_rows.h"

#include "scene.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

using S = PanelSection;

// Gravity, bounciness and the method are the lecture's ("Physics Engine Setup"), the frame rate
// and substeps the frame's: the Simulation section. The lecture's options of issue 16 (resolve,
// integrator, drag, the mistakes) and friction: the Physics section.
const std::vector<PanelRow> kPanelRows = {
    {"method", S::Simulation, 1, "method", 0.0f, 0.0f, "", false, "", "",
     "perfect: events in time order, no overlap\nmove-and-correct: move, then push "
     "apart\nturn-based: one body at a time"},
    {"bounciness", S::Simulation, 2, "bounciness C", 0.0f, 1.0f, "%.2f", false, "", "",
     "Coefficient of restitution: 1 elastic, 0 perfectly inelastic"},
    {"gravity", S::Simulation, 3, "gravity", -20.0f, 20.0f, "%.2f", false, "9.81",
     "Gravity 9.81 m/s² down", "Gravity (x, y) in m/s² (Ctrl+click to type a value)"},
    {"dt", S::Simulation, 4, "frame rate", 5.0f, 240.0f, "%.0f Hz", false, "", "",
     "Simulation frames per simulated second: dt = 1 / rate"},
    {"substeps", S::Simulation, 5, "substeps", 1.0f, 32.0f, "%d"},
    {"resolve", S::Physics, 1, "resolve", 0.0f, 0.0f, "", false, "", "",
     "momentum: with Newton, the lecture's formula u = (m1·v1 + m2·v2)/(m1 + m2), "
     "v' = u - C·(v - u)\nreflect: without Newton, each body reverses its own component as "
     "off a wall, v' = -C·v (momentum is not kept)\n(slide \"Demo: bouncing squares; "
     "with/without Newton\")"},
    {"integrator", S::Physics, 2, "integrator", 0.0f, 0.0f, "", false, "", "",
     "semi-implicit-euler: v += a·h, then x += v·h (the lecture's)\nexplicit-euler: x moves "
     "with the old v\nexact: x += v·h + a·h²/2, the parabola (slide \"It is just an "
     "approximation of the true movement!\")"},
    {"drag", S::Physics, 3, "drag k", 0.0f, 1000.0f, "%.3g kg/m³", true, "", "",
     "Quadratic drag: force -k·A·|v|·v, A = w·h; terminal speed sqrt(m·g/(k·A)). Air 1.2, "
     "water 1000 (slide \"Viscosity/drag: a feather falls slower than a stone\"; Ctrl+click "
     "to type)"},
    // µ is U+00B5 (the micro sign): the panel's font has Latin-1, not Greek.
    {"friction", S::Physics, 4, "friction µ", 0.0f, 2.0f, "%.2f", false, "", "",
     "Coulomb friction at every contact: along the face the relative velocity changes by at "
     "most µ times the change across it, toward zero, never past it; a block sliding on the "
     "floor stops after v0/(µ·g) s and v0²/(2·µ·g) m. A pair uses sqrt(µ1·µ2) (Box2D's rule; a "
     "block's own \"friction\" overrides the world's). 0: none (slide \"Application: "
     "Platformer\": moving platforms, friction, pushing objects)"},
    {"mistakes", S::Physics, 5, "Mistakes (the Tips slides' bugs)"},
};

// The "Selected block" section's fields.
const std::vector<BlockPanelRow> kBlockPanelRows = {
    {"position", "position", "(%.2f, %.2f) m", ""},
    {"size", "size", "%.2f m", ""},
    {"velocity", "velocity", "%.2f m/s", ""},
    {"mass", "mass", "%.3g kg", ""},
    {"force", "force", "%.2f N",
     "A constant force on the block (N), a = F/m (Ctrl+click to type); its arrow is drawn with "
     "the arrows overlay"},
};

} // namespace

const std::vector<PanelRow>& panelRows() {
    return kPanelRows;
}

const PanelRow* panelRowOf(const settings_table::WorldKey& row) {
    for (const PanelRow& p : kPanelRows)
        if (std::strcmp(p.key, row.key) == 0) return &p;
    return nullptr;
}

const std::vector<BlockPanelRow>& blockPanelRows() {
    return kBlockPanelRows;
}

const BlockPanelRow& blockPanelRow(const char* key) {
    for (const BlockPanelRow& p : kBlockPanelRows)
        if (std::strcmp(p.key, key) == 0) return p;
    std::fprintf(stderr, "blockPanelRow: no block field \"%s\" on the panel\n", key);
    std::abort();
}

const std::vector<const settings_table::WorldKey*>& panelOrder() {
    static const std::vector<const settings_table::WorldKey*> rows = [] {
        constexpr int kLast = 1000000; // a row not on the panel: after the panel's
        auto rank = [](const settings_table::WorldKey& k) {
            const PanelRow* p = panelRowOf(k);
            return p ? static_cast<int>(p->section) * 1000 + p->place : kLast;
        };
        std::vector<const settings_table::WorldKey*> out;
        for (const settings_table::WorldKey& row : settings_table::worldKeys())
            if (row.inScene) out.push_back(&row);
        std::stable_sort(out.begin(), out.end(),
                         [rank](const settings_table::WorldKey* a,
                                const settings_table::WorldKey* b) { return rank(*a) < rank(*b); });
        return out;
    }();
    return rows;
}

bool usesPhysicsSection(const Scene& scene, bool thrustOn) {
    if (thrustOn) return true;
    const WorldSettings defaults = defaultWorldSettings();
    for (const settings_table::WorldKey& row : settings_table::worldKeys()) {
        const PanelRow* p = panelRowOf(row);
        if (p && p->section == PanelSection::Physics &&
            !settings_table::same(row, scene.settings, defaults))
            return true;
    }
    for (const BlockDef& b : scene.blocks) {
        if (b.force != Vec2{} || b.friction >= 0.0) return true;
    }
    return false;
}
