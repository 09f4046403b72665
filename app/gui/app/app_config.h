// The app's own settings that persist between runs (ImGui keeps window placement in its ini):
// the last scene, the UI scale and the window size. A small "key = value" text file under
// $XDG_CONFIG_HOME/collision-sandbox/ (or ~/.config/collision-sandbox/).
#pragma once

#include "view.h" // the UI and label scales' ranges

#include <cstddef>
#include <string>
#include <vector>

struct App;
struct Options;

// A settings file larger than this is not read (defaults and a warning): 1 MiB.
inline constexpr std::size_t kMaxSettingsBytes = std::size_t{1} << 20;
// Bad lines warned about one by one; the rest are counted in one more warning.
inline constexpr std::size_t kMaxSettingsWarnings = 20;

struct AppConfig {
    std::string lastScene;         // an absolute path
    std::size_t lastSceneLine = 0; // its line in the file, for a warning
    float uiScale = 1.0f;
    bool lightTheme = false;
    float labelScale = 1.0f; // scene labels relative to the UI font
    bool existed = false;    // loaded from a file (false: the first launch)
    int windowWidth = 1280;
    int windowHeight = 720;
    int sound = -1;      // the knocks (M): -1 not chosen (on in lessons only), 0 off, 1 on
    float volume = 0.8f; // of the knocks, 0..1
};

// Parses the file's text; a hand-edited file never stops the app from starting: a line that is
// not "key = value", an unknown key, NaN or a value that is not a number keep the default, a value
// beyond its range is clamped, and each is a warning "FILE:LINE: ..." (when `warnings` is given).
AppConfig parseAppConfig(const std::string& text, const std::string& file = "settings.txt",
                         std::vector<std::string>* warnings = nullptr);
std::string formatAppConfig(const AppConfig& config);

// The directory for the app's files ("" when neither $XDG_CONFIG_HOME nor $HOME is set).
std::string configDirectory();
// Loads `dir`/settings.txt; defaults when missing. Never blocks and never reads more than
// kMaxSettingsBytes: a FIFO, a device, a directory, a file too large or unreadable gives the
// defaults and a warning naming the file; a last scene that is not an absolute path to a regular
// file is dropped with a warning naming its line.
AppConfig loadAppConfig(const std::string& dir, std::vector<std::string>* warnings = nullptr);
// Writes `dir`/settings.txt through a SafeFile, creating `dir`; a settings.txt that is not a
// regular file is replaced by one. False on failure (the app carries on).
bool saveAppConfig(const std::string& dir, const AppConfig& config);

// The settings and the app, glued once for the three mains (window, offscreen, browser): the
// saved settings under what the command line says (--ui-scale, --theme, --present) give the
// starting app its UI scale, theme, label size and knocks. The offscreen renderer passes the
// defaults (its images never depend on a file). `pixelRatio`: the browser's device pixel ratio,
// which the UI scale includes on screen and leaves out in the file.
void applyStartSettings(App& app, const AppConfig& config, const Options& options,
                        double pixelRatio = 1.0);
// What the settings keep of the app, when the window closes or the browser's page changes: the UI
// scale (without `pixelRatio`), the theme, the label size, the knocks' choice and volume. The
// last scene and the window's size are each main's own.
void keepSettings(const App& app, AppConfig& config, double pixelRatio = 1.0);
