#include "app_config.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

std::string trim(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    const auto last = s.find_last_not_of(" \t\r");
    return s.substr(first, last - first + 1);
}

template <typename T> bool parseNumber(const std::string& text, T& out) {
    std::istringstream in(text);
    T value{};
    if (!(in >> value)) return false;
    in >> std::ws;
    if (!in.eof()) return false;
    out = value;
    return true;
}

} // namespace

AppConfig parseAppConfig(const std::string& text) {
    AppConfig config;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const auto eq = line.find('=');
        if (line.empty() || line[0] == '#' || eq == std::string::npos) continue;
        const std::string key = trim(line.substr(0, eq));
        const std::string value = trim(line.substr(eq + 1));
        if (key == "last_scene") {
            config.lastScene = value;
        } else if (key == "ui_scale") {
            float s = 1.0f;
            if (parseNumber(value, s) && s == s) {
                config.uiScale = std::clamp(s, kMinUiScale, kMaxUiScale);
            }
        } else if (key == "light_theme") {
            config.lightTheme = value == "1" || value == "true";
        } else if (key == "label_scale") {
            float s = 1.0f;
            if (parseNumber(value, s) && s == s) {
                config.labelScale = std::clamp(s, kMinLabelScale, kMaxLabelScale);
            }
        } else if (key == "sound") {
            if (value == "on") config.sound = 1;
            if (value == "off") config.sound = 0;
        } else if (key == "volume") {
            float v = 0.8f;
            if (parseNumber(value, v) && v == v) config.volume = std::clamp(v, 0.0f, 1.0f);
        } else if (key == "window_width") {
            int w = 0;
            if (parseNumber(value, w)) config.windowWidth = std::clamp(w, 320, 16384);
        } else if (key == "window_height") {
            int h = 0;
            if (parseNumber(value, h)) config.windowHeight = std::clamp(h, 240, 16384);
        }
    }
    return config;
}

std::string formatAppConfig(const AppConfig& config) {
    std::ostringstream out;
    out << "# collision sandbox settings (written on exit)\n";
    out << "last_scene = " << config.lastScene << "\n";
    out << "ui_scale = " << config.uiScale << "\n";
    out << "light_theme = " << (config.lightTheme ? 1 : 0) << "\n";
    out << "label_scale = " << config.labelScale << "\n";
    out << "window_width = " << config.windowWidth << "\n";
    out << "window_height = " << config.windowHeight << "\n";
    if (config.sound >= 0) out << "sound = " << (config.sound ? "on" : "off") << "\n";
    out << "volume = " << config.volume << "\n";
    return out.str();
}

std::string configDirectory() {
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    if (xdg && *xdg) return std::string(xdg) + "/collision-sandbox";
    const char* home = std::getenv("HOME");
    if (home && *home) return std::string(home) + "/.config/collision-sandbox";
    return "";
}

AppConfig loadAppConfig(const std::string& dir) {
    if (dir.empty()) return {};
    std::ifstream in(dir + "/settings.txt");
    if (!in) return {};
    std::stringstream text;
    text << in.rdbuf();
    AppConfig config = parseAppConfig(text.str());
    config.existed = true;
    return config;
}

bool saveAppConfig(const std::string& dir, const AppConfig& config) {
    if (dir.empty()) return false;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return false;
    std::ofstream out(dir + "/settings.txt");
    if (!out) return false;
    out << formatAppConfig(config);
    return static_cast<bool>(out);
}
