#include "lesson_guards.h"

#include "printable.h"
#include "safe_file.h"
#include "scene_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace scene_json;

namespace lesson_guards {

namespace {

bool isRegularFile(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec);
}

} // namespace

std::string quoted(const std::string& s) {
    return "\"" + printable(s) + "\"";
}

std::string text(const json& value, const std::string& path, std::size_t maxLines,
                 std::size_t maxLineChars) {
    const std::string s = string(value, path);
    if (s.empty()) throw ValueError{path, "must not be empty"};
    std::size_t lines = 1, lineChars = 0;
    for (const char c : s) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '\n') {
            if (++lines > maxLines)
                throw ValueError{path, maxLines == 1 ? "must be one line"
                                                     : "must be at most " +
                                                           std::to_string(maxLines) + " lines"};
            lineChars = 0;
            continue;
        }
        if (byte < 0x20 || byte == 0x7f) throw ValueError{path, "has a control character"};
        if ((byte & 0xc0) != 0x80 && ++lineChars > maxLineChars) // count UTF-8 characters
            throw ValueError{path, "has a line longer than " + std::to_string(maxLineChars) +
                                       " characters"};
    }
    return s;
}

int blockIndex(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.blocks.size(); ++i)
        if (scene.blocks[i].name == name) return static_cast<int>(i);
    return -1;
}

int requireBlock(const Scene& scene, const json& value, const std::string& path) {
    const std::string name = string(value, path);
    const int i = blockIndex(scene, name);
    if (i < 0) throw ValueError{path, "no block named " + quoted(name) + " in the step's scene"};
    return i;
}

std::vector<std::string> overlayList(const json& value, const std::string& path,
                                     const std::vector<std::string>& known) {
    if (!value.is_array()) throw ValueError{path, "must be an array of overlay names"};
    std::vector<std::string> names;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string p = indexPath(path, i);
        const std::string name = string(value[i], p);
        if (!known.empty() && std::find(known.begin(), known.end(), name) == known.end()) {
            std::string list;
            for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
            throw ValueError{p, "unknown overlay " + quoted(name) + " (expected " + list + ")"};
        }
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    return names;
}

std::string findSceneFile(const std::string& name, const SceneFolders& context,
                          const std::string& scenePath) {
    const fs::path p(name);
    if (p.is_absolute())
        throw ValueError{scenePath, quoted(name) + " is an absolute path: a lesson names its "
                                                   "scenes relative to its own folder"};
    const fs::path base = context.baseDir.empty() ? fs::path(".") : fs::path(context.baseDir);
    std::error_code ec;
    const fs::path folder = fs::weakly_canonical(base, ec);
    const fs::path file = fs::weakly_canonical(base / p, ec);
    const bool inside =
        !ec &&
        std::mismatch(folder.begin(), folder.end(), file.begin(), file.end()).first == folder.end();
    std::error_code statusError;
    const fs::file_status status = fs::status(base / p, statusError);
    if (statusError == std::errc::too_many_symbolic_link_levels)
        throw ValueError{scenePath, quoted(name) + " is " + unfollowablePathWhy(statusError)};
    if (fs::exists(status) && !p.empty()) {
        if (!inside) throw ValueError{scenePath, quoted(name) + " is outside the lesson's folder"};
        if (!fs::is_regular_file(status))
            throw ValueError{scenePath, quoted(name) + " is not a regular file (a directory, a "
                                                       "device or a FIFO)"};
        if (!context.lessonFile.empty() && sameExistingFile(file.string(), context.lessonFile))
            throw ValueError{scenePath, quoted(name) + " is the lesson file itself"};
        return (base / p).lexically_normal().string();
    }
    if (!inside) throw ValueError{scenePath, quoted(name) + " is outside the lesson's folder"};
    if (context.scenesDir.empty() || name.empty() || name.find('/') != std::string::npos ||
        name == "." || name == "..")
        return "";
    for (const fs::path& c :
         {fs::path(context.scenesDir) / p, fs::path(context.scenesDir) / (name + ".json")})
        if (isRegularFile(c)) return c.lexically_normal().string();
    return "";
}

} // namespace lesson_guards
