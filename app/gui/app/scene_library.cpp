#include "scene_library.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
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

// The name a scene file gives itself, read in one pass over its JSON without making the scene
// (listing the shipped scenes made each whole, the largest part of the browser's first frame):
// `scene` when the top level is an object with a string "name" and only a scene's keys (a lesson,
// with its "steps", is not a scene). A shipped scene is valid (tests/scenes); a broken file with
// a name would show that name rather than its file's.
class SceneNameReader : public nlohmann::json_sax<nlohmann::json> {
  public:
    std::string name;
    bool named = false; // a string "name" at the top level
    bool scene = true;  // every top-level key one of a scene's, the top level an object

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool string(string_t& s) override {
        if (depth_ == 1 && key_ == "name") {
            name = s;
            named = true;
            return true;
        }
        return value();
    }
    bool start_object(std::size_t) override { return open(depth_ == 0); }
    bool start_array(std::size_t) override { return open(false); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }
    bool key(string_t& k) override {
        if (depth_ == 1) {
            // The scene format's top-level keys (engine/scene/scene.cpp's parseScene).
            static const std::array<const char*, 6> kSceneKeys = {
                "name", "description", "duration", "world", "blocks", "player"};
            scene = scene && std::find(kSceneKeys.begin(), kSceneKeys.end(), k) != kSceneKeys.end();
            key_ = k;
        }
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
        scene = false;
        return false;
    }

  private:
    int depth_ = 0;
    std::string key_;
    bool value() { // not a string
        if (depth_ == 0 || (depth_ == 1 && key_ == "name")) scene = false;
        return true;
    }
    bool open(bool topLevelObject) {
        if (!topLevelObject) value();
        ++depth_;
        return true;
    }
    bool close() {
        --depth_;
        return true;
    }
};

// The title listScenes gives the file: its scene's name, the file's name when the scene's is
// empty, and when it is no scene the file's name with underscores as spaces.
std::string sceneTitle(const fs::path& p) {
    std::ifstream in(p, std::ios::binary | std::ios::ate); // read whole (not char by char)
    std::string text(static_cast<std::size_t>(std::max<std::streamoff>(0, in.tellg())), '\0');
    in.seekg(0);
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    SceneNameReader reader;
    const bool scene =
        in && nlohmann::json::sax_parse(text, &reader) && reader.scene && reader.named;
    if (scene && !reader.name.empty()) return reader.name;
    std::string title = p.stem().string();
    if (!scene) std::replace(title.begin(), title.end(), '_', ' ');
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
