#include "scene_library.h"

#include "scene_json.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
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

// The title listScenes gives the file: its scene's name, the file's name when the scene's is
// empty, and when it is no scene the file's name with underscores as spaces. The name is read in
// one pass (sceneNameOf) without making the scene: listing the shipped scenes made each whole
// before, the largest part of the browser's first frame.
std::string sceneTitle(const fs::path& p) {
    std::ifstream in(p, std::ios::binary | std::ios::ate); // read whole (not char by char)
    std::string text(static_cast<std::size_t>(std::max<std::streamoff>(0, in.tellg())), '\0');
    in.seekg(0);
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    const std::optional<std::string> name = in ? sceneNameOf(text) : std::nullopt;
    if (name && !name->empty()) return *name;
    std::string title = p.stem().string();
    if (!name) std::replace(title.begin(), title.end(), '_', ' ');
    return title;
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
    std::vector<std::string> order; // file names in the lecture's order
    std::ifstream orderFile(fs::path(dir) / kSceneOrderFile);
    for (std::string line; std::getline(orderFile, line);) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (!line.empty() && line[0] != '#') order.push_back(line);
    }
    std::vector<std::size_t> rank;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path& p = it->path();
        if (p.extension() != ".json" || !isFile(p)) continue;
        entries.push_back({p.string(), sceneTitle(p)});
        const auto at = std::find(order.begin(), order.end(), p.filename().string());
        rank.push_back(static_cast<std::size_t>(at - order.begin()));
    }
    std::vector<std::size_t> index(entries.size());
    for (std::size_t i = 0; i < index.size(); ++i) index[i] = i;
    std::sort(index.begin(), index.end(), [&](std::size_t a, std::size_t b) {
        if (rank[a] != rank[b]) return rank[a] < rank[b];
        if (entries[a].title != entries[b].title) return entries[a].title < entries[b].title;
        return entries[a].path < entries[b].path;
    });
    std::vector<SceneEntry> sorted;
    sorted.reserve(entries.size());
    for (std::size_t i : index) sorted.push_back(entries[i]);
    return sorted;
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
