#include "app_config.h"

#include "app.h"
#include "options.h"
#include "printable.h"
#include "safe_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
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

std::string shortNumber(float v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

} // namespace

AppConfig parseAppConfig(const std::string& text, const std::string& file,
                         std::vector<std::string>* warnings) {
    AppConfig config;
    std::istringstream in(text);
    std::string line;
    std::size_t number = 0, warned = 0;
    // "FILE:LINE: WHAT" (the line's text escaped and cut); after kMaxSettingsWarnings, one count.
    const auto warn = [&](const std::string& what) {
        ++warned;
        if (warnings && warned <= kMaxSettingsWarnings)
            warnings->push_back(printable(file, kPrintablePath) + ":" + std::to_string(number) +
                                ": " + what + "; the default is used");
    };
    const auto quoted = [](const std::string& s) { return "'" + printable(s) + "'"; };
    // A number in [lo, hi]; NaN and junk are refused, a value beyond the range is clamped.
    const auto number01 = [&](const std::string& key, const std::string& value, float lo, float hi,
                              float& to) {
        float v = 0.0f;
        if (!parseNumber(value, v) || !std::isfinite(v))
            return warn(key + ": " + quoted(value) + " is not a number");
        if (v < lo || v > hi)
            warn(key + ": " + quoted(value) + " is outside " + shortNumber(lo) + " to " +
                 shortNumber(hi) + ", clamped");
        to = std::clamp(v, lo, hi);
    };
    const auto whole = [&](const std::string& key, const std::string& value, int lo, int hi,
                           int& to) {
        int v = 0;
        if (!parseNumber(value, v))
            return warn(key + ": " + quoted(value) + " is not a whole number");
        if (v < lo || v > hi)
            warn(key + ": " + quoted(value) + " is outside " + std::to_string(lo) + " to " +
                 std::to_string(hi) + ", clamped");
        to = std::clamp(v, lo, hi);
    };
    while (std::getline(in, line)) {
        ++number;
        if (trim(line).empty() || line[0] == '#') continue;
        const auto eq = line.find('=');
        if (eq == std::string::npos) {
            warn("not a 'key = value' line: " + quoted(line));
            continue;
        }
        const std::string key = trim(line.substr(0, eq));
        const std::string value = trim(line.substr(eq + 1));
        if (key == "last_scene") {
            config.lastScene = value;
            config.lastSceneLine = number;
        } else if (key == "ui_scale") {
            number01(key, value, kMinUiScale, kMaxUiScale, config.uiScale);
        } else if (key == "light_theme") {
            if (value != "0" && value != "1" && value != "true" && value != "false")
                warn("light_theme: " + quoted(value) + " is not 0 or 1");
            config.lightTheme = value == "1" || value == "true";
        } else if (key == "label_scale") {
            number01(key, value, kMinLabelScale, kMaxLabelScale, config.labelScale);
        } else if (key == "sound") {
            if (value == "on")
                config.sound = 1;
            else if (value == "off")
                config.sound = 0;
            else
                warn("sound: " + quoted(value) + " is not on or off");
        } else if (key == "volume") {
            number01(key, value, 0.0f, 1.0f, config.volume);
        } else if (key == "window_width") {
            whole(key, value, 320, 16384, config.windowWidth);
        } else if (key == "window_height") {
            whole(key, value, 240, 16384, config.windowHeight);
        } else {
            warn("unknown key " + quoted(key));
        }
    }
    if (warnings && warned > kMaxSettingsWarnings)
        warnings->push_back(printable(file, kPrintablePath) + ": " +
                            std::to_string(warned - kMaxSettingsWarnings) + " more bad lines");
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

AppConfig loadAppConfig(const std::string& dir, std::vector<std::string>* warnings) {
    if (dir.empty()) return {};
    const std::string path = dir + "/settings.txt";
    const auto warn = [&](const std::string& what) {
        if (warnings)
            warnings->push_back(printable(path, kPrintablePath) + ": " + what +
                                "; the defaults are used");
    };
    // Never blocks (a FIFO opens without a writer) and reads only a regular file, at most
    // kMaxSettingsBytes of it: a device (/dev/zero) or a directory is refused before a byte.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        if (errno == ELOOP)
            warn(unfollowablePathWhy(std::error_code(errno, std::generic_category())));
        else if (errno != ENOENT)
            warn(std::string("cannot read (") + std::strerror(errno) + ")");
        return {};
    }
    struct stat st {};
    std::string text;
    bool readable = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    if (!readable) {
        warn("not a regular file");
    } else {
        text.resize(kMaxSettingsBytes + 1);
        std::size_t got = 0;
        while (got < text.size()) {
            const ssize_t n = ::read(fd, text.data() + got, text.size() - got);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) break;
            got += static_cast<std::size_t>(n);
        }
        text.resize(got);
        if (got > kMaxSettingsBytes) warn("larger than 1 MiB"), readable = false;
    }
    ::close(fd);
    if (!readable) return {};
    AppConfig config = parseAppConfig(text, path, warnings);
    config.existed = true;
    // The last scene must still be a file that can be opened (not a device, FIFO, directory,
    // nor gone) and absolute (a relative one means another folder from another start).
    if (!config.lastScene.empty()) {
        struct stat scene {};
        std::string why;
        if (config.lastScene[0] != '/')
            why = "is not an absolute path";
        else if (::stat(config.lastScene.c_str(), &scene) != 0)
            why = errno == ELOOP
                      ? "is " + unfollowablePathWhy(std::error_code(errno, std::generic_category()))
                      : "is gone";
        else if (!S_ISREG(scene.st_mode))
            why = "is not a regular file";
        if (!why.empty()) {
            if (warnings)
                warnings->push_back(printable(path, kPrintablePath) + ":" +
                                    std::to_string(config.lastSceneLine) + ": last_scene " +
                                    printable(config.lastScene, kPrintablePath) + " " + why +
                                    "; the default scene opens");
            config.lastScene.clear();
        }
    }
    return config;
}

bool saveAppConfig(const std::string& dir, const AppConfig& config) {
    if (dir.empty()) return false;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return false;
    // A settings.txt that is not a regular file of this folder (a FIFO, a device node, a link to
    // one or to a file in another folder, an empty directory) is replaced, not written through:
    // nothing is written outside this folder.
    const std::string path = dir + "/settings.txt";
    std::error_code targetError, dirError;
    const std::filesystem::path target = std::filesystem::canonical(path, targetError);
    const bool inside = !targetError &&
                        target.parent_path() == std::filesystem::canonical(dir, dirError) &&
                        !dirError;
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && (!S_ISREG(st.st_mode) || !inside))
        std::filesystem::remove(path, ec);
    return writeFileSafely(path, formatAppConfig(config));
}

void applyStartSettings(App& app, const AppConfig& config, const Options& options,
                        double pixelRatio) {
    const float scale = options.uiScale > 0.0f ? options.uiScale : config.uiScale;
    setUiScale(app.view, static_cast<float>(scale * pixelRatio));
    app.view.lightTheme = options.theme.empty() ? config.lightTheme : options.theme == "light";
    app.view.labelScale = config.labelScale;
    app.sim.sound.chosen = config.sound >= 0;
    app.sim.sound.on = config.sound == 1;
    app.sim.sound.volume = config.volume;
    if (options.present) setPresentMode(app.view, true);
}

void keepSettings(const App& app, AppConfig& config, double pixelRatio) {
    config.uiScale = static_cast<float>(app.view.uiScale / pixelRatio);
    config.lightTheme = app.view.lightTheme;
    config.labelScale = app.view.labelScale;
    config.sound = app.sim.sound.chosen ? (app.sim.sound.on ? 1 : 0) : -1;
    config.volume = app.sim.sound.volume;
}
