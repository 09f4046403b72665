// The app's own settings that persist between runs (ImGui keeps window placement in its ini):
// the last scene, the UI scale and the window size. A small "key = value" text file under
// $XDG_CONFIG_HOME/collision-sandbox/ (or ~/.config/collision-sandbox/).
#pragma once

#include "view.h" // the UI and label scales' ranges

#include <string>

struct AppConfig {
    std::string lastScene; // an absolute path
    float uiScale = 1.0f;
    bool lightTheme = false;
    float labelScale = 1.0f; // scene labels relative to the UI font
    bool existed = false;    // loaded from a file (false: the first launch)
    int windowWidth = 1280;
    int windowHeight = 720;
    int sound = -1;      // the knocks (M): -1 not chosen (on in lessons only), 0 off, 1 on
    float volume = 0.8f; // of the knocks, 0..1
};

// Parses the file's text; unknown keys and bad values are ignored (a hand-edited file never
// stops the app from starting). Values are clamped to sane ranges.
AppConfig parseAppConfig(const std::string& text);
std::string formatAppConfig(const AppConfig& config);

// The directory for the app's files ("" when neither $XDG_CONFIG_HOME nor $HOME is set).
std::string configDirectory();
// Loads `dir`/settings.txt; defaults when missing.
AppConfig loadAppConfig(const std::string& dir);
// Writes `dir`/settings.txt, creating `dir`. False on failure (the app carries on).
bool saveAppConfig(const std::string& dir, const AppConfig& config);
