// The controls panel's sections that edit the world and its blocks: the world's settings, one
// widget per row of the settings table (settings_table.h) by its kind, in the Simulation and
// Physics sections, and the selected block's fields (the table's block rows).
#pragma once

struct App;

void simulationSection(App& app);
// Issue 16's settings (each a scene key, kept by R, restored by Shift+R, saved by Ctrl+S) and the
// keyboard thrust (the app's own: kept by both resets, set by a lesson step).
void physicsSection(App& app);
// The selected block: its kind, mass, force, size and velocity, or how to select or add one.
void selectedSection(App& app);
