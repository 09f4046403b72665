#include "scene_library.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace {

bool isDirectory(const fs::path& p) {
    std::error_code ec;
    return fs::is_directory(p, ec);
}

bool isFile(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec);
}

} // namespace

std::string executableDirectory() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return "";
    return exe.parent_path().string();
}

std::string findScenesDirectory(const std::string& exeDir, const std::string& builtInDir) {
    return findDataDirectory(exeDir, builtInDir, "scenes");
}

std::string findDataDirectory(const std::string& exeDir, const std::string& builtInDir,
                              const std::string& folder) {
    std::vector<fs::path> candidates;
    if (!exeDir.empty()) {
        candidates.push_back(fs::path(exeDir) / folder);
        candidates.push_back(fs::path(exeDir) / ".." / "share" / "collision-sandbox" / folder);
    }
    if (!builtInDir.empty()) candidates.push_back(builtInDir);
    candidates.push_back(fs::path("app") / folder);
    candidates.push_back(folder);
    for (const fs::path& c : candidates) {
        if (isDirectory(c)) return c.lexically_normal().string();
    }
    return "";
}

std::vector<SceneEntry> listScenes(const std::string& dir) {
    std::vector<SceneEntry> entries;
    if (dir.empty()) return entries;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path& p = it->path();
        if (p.extension() != ".json" || !isFile(p)) continue;
        std::string title = p.stem().string();
        std::replace(title.begin(), title.end(), '_', ' ');
        entries.push_back({p.string(), title});
    }
    std::sort(entries.begin(), entries.end(),
              [](const SceneEntry& a, const SceneEntry& b) { return a.path < b.path; });
    return entries;
}

std::string resolveScenePath(const std::string& arg, const std::string& scenesDir) {
    if (arg.empty() || isFile(arg)) return arg;
    if (!scenesDir.empty()) {
        const fs::path inDir = fs::path(scenesDir) / arg;
        if (isFile(inDir)) return inDir.string();
        const fs::path withExt = fs::path(scenesDir) / (arg + ".json");
        if (isFile(withExt)) return withExt.string();
    }
    return arg;
}
