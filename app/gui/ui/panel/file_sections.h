// The controls panel's sections about the scene's file: the scene picker at the panel's top
// (the shipped scenes and lessons, the browser's Copy link), Open and save (the edit log too), and
// Compare your engine's trace (docs/compare.md).
#pragma once

struct App;

void scenePicker(App& app);
void fileSection(App& app);
// Check your own engine: a trace the student's engine printed, opened on the current scene and
// compared with it; the units it is in.
void compareSection(App& app);
