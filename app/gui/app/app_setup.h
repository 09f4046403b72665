// Starting the app from the command line: find the shipped scenes, pick the scene to open (the
// argument, else the last one used, else the default) and load it.
#pragma once

#include "app.h"
#include "options.h"

#include <string>

// The shipped scenes directory compiled in (the source tree's app/scenes).
std::string builtInScenesDirectory();

// Fills app.shipped.scenesDir and app.shipped.scenes and loads the first scene that loads among:
// the command-line scene (an error if it fails: returns false with `error`), `lastScene`, the
// default scene. When none loads, the app starts with an empty world and shows why.
bool setupApp(App& app, const Options& options, const std::string& lastScene, std::string* error);
