// The controls panel's columns of the settings table (engine/scene/settings_table.h), on the
// app's side: where a world setting sits on the panel (its section and place), its label, the
// slider's range and number format, a pair's preset button and the tooltip; a block field's label,
// number format and tooltip. Each row is keyed by the engine row's key (the engine's rows keep the
// key, the member, the range and unit, and the meaning); tests/app/state/panel_rows_test.cpp
// checks that every panel row names a real key and that its slider stays within the row's range.
#pragma once

#include "settings_table.h"

#include <cstdint>
#include <vector>

struct Scene;

// The panel's sections of world settings.
enum class PanelSection : std::uint8_t { Simulation, Physics };

// A world setting on the panel.
struct PanelRow {
    const char* key;
    PanelSection section;
    int place; // 1 first in its section
    const char* label;
    float min = 0.0f, max = 0.0f; // the slider's ends (a rate's: what it shows, in its unit)
    const char* format = "";      // the slider's number format, unit included
    bool logarithmic = false;
    const char* presetLabel = ""; // a pair's preset button: it sets the default value
    const char* presetTooltip = "";
    const char* tooltip = "";
};

// A block field on the panel's "Selected block" section.
struct BlockPanelRow {
    const char* key;
    const char* label;
    const char* format; // the field's number format, unit included
    const char* tooltip;
};

// The panel's rows of world settings, in no particular order.
const std::vector<PanelRow>& panelRows();
// The panel's row of a world setting, or null when the panel does not show it.
const PanelRow* panelRowOf(const settings_table::WorldKey& row);
// The panel's block fields; blockPanelRow's key must be one of them (a typo is a programming
// error).
const std::vector<BlockPanelRow>& blockPanelRows();
const BlockPanelRow& blockPanelRow(const char* key);

// The scene's world settings in the panel's order (Simulation, then Physics, each by place, then
// any setting not on the panel, in table order): the panel draws them and the --verbose log
// describes changes so.
const std::vector<const settings_table::WorldKey*>& panelOrder();
// True when the scene uses the Physics section (it opens then): the thrust is on, a setting of
// that section differs from its default, or a block has its own force or friction.
bool usesPhysicsSection(const Scene& scene, bool thrustOn);
