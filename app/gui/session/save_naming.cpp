#include "save_naming.h"

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
    return a.gravity != b.gravity || a.bounciness != b.bounciness || a.method != b.method ||
           a.dt != b.dt || a.substeps != b.substeps || a.resolve != b.resolve ||
           a.integrator != b.integrator || a.mistakes != b.mistakes || a.drag != b.drag;
}

bool hasUnsavedEdits(bool blocksEdited, const WorldSettings& scene, const WorldSettings& now) {
    return blocksEdited || settingsDiffer(scene, now);
}

std::string changedSettingsNote(const WorldSettings& original, const WorldSettings& now) {
    std::string parts;
    auto add = [&parts](const std::string& s) { parts += (parts.empty() ? " " : ", ") + s; };
    if (now.gravity != original.gravity) {
        add(now.gravity == Vec2{} ? std::string("no gravity")
                                  : "gravity (" + formatNumber(now.gravity.x) + ", " +
                                        formatNumber(now.gravity.y) + ") m/s²");
    }
    if (now.bounciness != original.bounciness) add("bounciness " + formatNumber(now.bounciness));
    if (now.method != original.method) add(std::string("method ") + methodName(now.method));
    if (now.dt != original.dt) add("frame rate " + formatNumber(1.0 / now.dt) + " Hz");
    if (now.substeps != original.substeps) add("substeps " + std::to_string(now.substeps));
    if (now.resolve != original.resolve) add(std::string("resolve ") + resolveName(now.resolve));
    if (now.integrator != original.integrator)
        add(std::string("integrator ") + integratorName(now.integrator));
    if (now.mistakes != original.mistakes) {
        std::string names;
        for (int m = 0; m < static_cast<int>(Mistake::Count); ++m) {
            if (!now.has(static_cast<Mistake>(m))) continue;
            names +=
                (names.empty() ? "" : " and ") + std::string(mistakeName(static_cast<Mistake>(m)));
        }
        add(names.empty() ? std::string("no mistakes") : "mistakes " + names);
    }
    if (now.drag != original.drag) add("drag " + formatNumber(now.drag) + " kg/m³");
    if (parts.empty()) return "";
    return std::string(kNoteStart) + parts + ".";
}

std::string savedDescription(const std::string& description, const WorldSettings& original,
                             const WorldSettings& now) {
    const std::string note = changedSettingsNote(original, now);
    if (note.empty()) return description;
    std::string text = description;
    while (!text.empty() && (text.back() == ' ' || text.back() == '\n')) text.pop_back();
    return text.empty() ? note : text + " " + note;
}
