#include "save_naming.h"

#include "input_limits.h"
#include "settings_table.h"
#include "text_format.h"

#include <cctype>
#include <filesystem>

namespace fs = std::filesystem;

namespace {

constexpr const char* kNoteStart = "Saved with changed settings:";

} // namespace

std::string sceneFileStem(const std::string& sceneName) {
    std::string stem;
    bool gap = false;
    for (char c : sceneName) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (std::isalnum(u) && u < 128) {
            if (gap && !stem.empty()) stem += '_';
            stem += static_cast<char>(std::tolower(u));
            gap = false;
        } else {
            gap = true;
        }
    }
    return stem.empty() ? "scene" : stem;
}

std::string absoluteScenePath(const std::string& path, const std::string& cwd) {
    if (path.empty()) return "";
    fs::path p(path);
    if (p.is_relative()) p = fs::path(cwd) / p;
    p = p.lexically_normal();
    if (!p.has_extension()) p += ".json";
    return p.string();
}

std::string suggestSavePath(const std::string& sceneName, const std::string& dir,
                            const std::function<bool(const std::string&)>& exists,
                            const std::string& extension) {
    const std::string stem = sceneFileStem(sceneName);
    const fs::path base(dir);
    const std::string first = (base / (stem + extension)).lexically_normal().string();
    if (!exists(first)) return first;
    for (int k = 2; k <= 999; ++k) {
        const std::string p =
            (base / (stem + "-" + std::to_string(k) + extension)).lexically_normal().string();
        if (!exists(p)) return p;
    }
    return first;
}

bool pathExists(const std::string& path) {
    std::error_code ec;
    return fs::exists(path, ec);
}

bool settingsDiffer(const WorldSettings& a, const WorldSettings& b) {
    return !settings_table::sameSceneSettings(a, b);
}

bool hasUnsavedEdits(bool blocksEdited, const WorldSettings& scene, const WorldSettings& now) {
    return blocksEdited || settingsDiffer(scene, now);
}

std::string changedSettingsNote(const WorldSettings& original, const WorldSettings& now) {
    std::string parts;
    for (const settings_table::WorldKey& row : settings_table::worldKeys()) {
        if (!row.inScene || settings_table::same(row, original, now)) continue;
        // "gravity (0, -9.81) m/s²", "frame rate 30 Hz", "method turn-based"; "no gravity".
        const std::string said = settings_table::isNone(row, now)
                                     ? "no " + std::string(row.shown.name)
                                     : row.shown.name + std::string(" ") +
                                           settings_table::shownValue(
                                               row, now, [](double v) { return formatNumber(v); });
        parts += (parts.empty() ? " " : ", ") + said;
    }
    if (parts.empty()) return "";
    return std::string(kNoteStart) + parts + ".";
}

std::string savedDescription(const std::string& description, const WorldSettings& original,
                             const WorldSettings& now) {
    const std::string note = changedSettingsNote(original, now);
    if (note.empty()) return description;
    std::string text = description;
    while (!text.empty() && (text.back() == ' ' || text.back() == '\n')) text.pop_back();
    text = text.empty() ? note : text + " " + note;
    // A description at its limit keeps its own words: the file must load again.
    return limits::textLengthViolation(text, limits::kMaxDescriptionChars).empty() ? text
                                                                                   : description;
}
