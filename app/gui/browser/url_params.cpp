#include "url_params.h"

#include "app.h"
#include "edit.h"
#include "lesson_session.h"
#include "page_world_controls.h"
#include "panel_rows.h"
#include "printable.h"
#include "scene_json.h"
#include "scene.h"
#include "scene_library.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <set>

namespace {

constexpr std::size_t kMaxEchoed = 40; // characters of a bad value quoted back

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

std::string percentDecode(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '+') {
            out += ' ';
        } else if (c == '%' && i + 2 < text.size() && hexDigit(text[i + 1]) >= 0 &&
                   hexDigit(text[i + 2]) >= 0) {
            out += static_cast<char>(hexDigit(text[i + 1]) * 16 + hexDigit(text[i + 2]));
            i += 2;
        } else {
            out += c;
        }
    }
    return out;
}

std::string echo(const std::string& text) {
    return "'" + printable(text, kMaxEchoed) + "'"; // controls escaped, long values cut
}

bool isSceneName(const std::string& name) {
    if (name.empty()) return false;
    for (const char c : name) {
        const auto u = static_cast<unsigned char>(c);
        if (!std::isalnum(u) && c != '_' && c != '-') return false;
    }
    return true;
}

// The known parameters' names, for the message about unknown ones.
std::string knownNames() {
    std::string names;
    for (const UrlParamInfo& info : kUrlParams)
        names += (names.empty() ? "" : ", ") + std::string(info.name);
    for (const settings_table::WorldKey* row : panelOrder())
        names += ", " + std::string(row->key);
    return names;
}

// "unknown URL parameter 'zoom' ignored (known: ...)", or for many "3 unknown URL parameters
// ignored: 'a', 'b', 'c' (known: ...)", naming at most a few.
std::string unknownLine(const std::vector<std::string>& unknown) {
    constexpr std::size_t kNamed = 3;
    std::string named;
    for (std::size_t i = 0; i < unknown.size() && i < kNamed; ++i)
        named += (i ? ", " : "") + echo(unknown[i]);
    if (unknown.size() > kNamed) named += ", ...";
    const std::string known = " (known: " + knownNames() + ")";
    if (unknown.size() == 1) return "unknown URL parameter " + named + " ignored" + known;
    return std::to_string(unknown.size()) + " unknown URL parameters ignored: " + named + known;
}

} // namespace

bool isTrackerParam(std::string_view name) {
    // Campaign tags (utm_*) and the click identifiers of ad and social networks and mailers.
    static constexpr std::string_view kTrackers[] = {
        "fbclid",  "gclid",    "gclsrc", "dclid",   "gbraid",    "wbraid",      "msclkid",
        "yclid",   "twclid",   "ttclid", "igshid",  "mc_cid",    "mc_eid",      "_ga",
        "_gl",     "_hsenc",   "_hsmi",  "mkt_tok", "li_fat_id", "oly_anon_id", "oly_enc_id",
        "vero_id", "wickedid", "s_cid",  "ref_src"};
    if (name.substr(0, 4) == "utm_") return true;
    for (const std::string_view t : kTrackers)
        if (name == t) return true;
    return false;
}

UrlParams parseUrlParams(const std::string& query) {
    UrlParams p;
    std::set<std::string> seen;
    std::vector<std::string> unknown;
    std::size_t start = !query.empty() && query[0] == '?' ? 1 : 0;
    while (start <= query.size()) {
        std::size_t end = query.find('&', start);
        if (end == std::string::npos) end = query.size();
        const std::string pair = query.substr(start, end - start);
        start = end + 1;
        if (pair.empty()) continue;
        const std::size_t eq = pair.find('=');
        const std::string key = percentDecode(pair.substr(0, eq));
        const std::string value = eq == std::string::npos ? "" : percentDecode(pair.substr(eq + 1));
        const std::string where = "URL parameter " + printable(key);
        if (isTrackerParam(key)) continue;
        const settings_table::WorldKey* worldKey = settings_table::findWorldKey(key);
        if (worldKey && !worldKey->inScene) worldKey = nullptr;
        const bool known =
            worldKey || std::any_of(std::begin(kUrlParams), std::end(kUrlParams),
                                    [&key](const UrlParamInfo& i) { return key == i.name; });
        if (!known) {
            unknown.push_back(key);
            continue;
        }
        if (!seen.insert(key).second) {
            p.errors.push_back(where + ": given twice (the first one counts)");
            continue;
        }
        if (worldKey) {
            const settings_table::FlagProblem problem = readWorldValue(*worldKey, value, p.world);
            if (problem.expected.empty())
                p.worldGiven.push_back(worldKey);
            else
                p.errors.push_back(where + ": " + echo(problem.text) + " " + problem.expected +
                                   ": not applied");
        } else if (key == "scene") {
            if (isSceneName(value))
                p.scene = value;
            else
                p.errors.push_back(where + ": " + echo(value) +
                                   " is not a scene name (letters, digits, _ and -)");
        } else if (key == "show" && value.empty()) { // a link's way to say: no overlay
            p.show = ShowSet{};
            p.showGiven = true;
        } else if (key == "show") {
            std::string error;
            ShowSet show;
            if (parseShowList(value, show, &error)) {
                p.show = show;
                p.showGiven = true;
            } else {
                p.errors.push_back(where + ": " + error);
            }
        } else if (key == "frame") {
            p.frame = parseViewFrame(value);
            if (!p.frame)
                p.errors.push_back(where + ": unknown frame " + echo(value) + " (world, com)");
        } else if (key == "lesson") {
            if (isSceneName(value))
                p.lesson = value;
            else
                p.errors.push_back(where + ": " + echo(value) +
                                   " is not a lesson name (letters, digits, _ and -)");
        } else if (key == "step") { // its range is the lesson's: applyUrlParams checks it
            const bool digits = !value.empty() && value.size() <= 9 &&
                                value.find_first_not_of("0123456789") == std::string::npos;
            p.step = digits && std::stoi(value) > 0 ? std::stoi(value) : -1;
            p.stepText = value;
        }
    }
    if (p.step != 0 && p.lesson.empty()) {
        p.errors.push_back("URL parameter step: needs a lesson (lesson=NAME)");
        p.step = 0;
    }
    // A link with thousands of bad parameters still leaves the panel its controls: a few lines.
    if (p.errors.size() > kMaxUrlErrors) {
        const std::size_t more = p.errors.size() - kMaxUrlErrors;
        p.errors.resize(kMaxUrlErrors);
        p.errors.push_back("... and " + std::to_string(more) + " more problems in the URL");
    }
    if (!unknown.empty()) p.errors.push_back(unknownLine(unknown));
    return p;
}

void applyUrlParams(App& app, const UrlParams& params) {
    std::string errors;
    auto add = [&errors](const std::string& e) { errors += (errors.empty() ? "" : "\n") + e; };
    for (const std::string& e : params.errors) add(e);
    if (!params.lesson.empty()) {
        const std::string path = app.shipped.lessonsDir + "/" + params.lesson + ".json";
        bool shipped = false;
        for (const SceneEntry& s : app.shipped.lessons) shipped = shipped || s.path == path;
        if (!shipped)
            add("URL parameter lesson: no lesson " + echo(params.lesson) + " is shipped");
        else if (!openLesson(app, path, 0))
            add(app.ui.messages.error);
        else {
            const int steps = static_cast<int>(app.lesson.lesson->steps.size());
            if (params.step >= 2 && params.step <= steps)
                openLesson(app, path, static_cast<std::size_t>(params.step - 1));
            else if (params.step != 0 && params.step != 1)
                add("URL parameter step: " + echo(params.stepText) + " is not a step of " +
                    echo(params.lesson) + " (1 to " + std::to_string(steps) +
                    "): it opens at step 1");
            if (!params.linkScene.empty()) {
                // The step's setup as the student changed it (link.h).
                const SceneResult carried = loadSceneFile(params.linkScene);
                if (carried.scene)
                    lessonTakeSetup(app.lesson, app.sim, app.view, *carried.scene);
                else
                    add("the link's scene (#scene=...): " + carried.error.text());
            }
        }
    }
    if (!params.linkScene.empty() && params.lesson.empty()) {
        if (!loadScene(app, params.linkScene))
            add("the link's scene (#scene=...): " + app.ui.messages.error);
    } else if (!params.scene.empty()) {
        const std::string path = app.shipped.scenesDir + "/" + params.scene + ".json";
        bool shipped = false;
        for (const SceneEntry& s : app.shipped.scenes) shipped = shipped || s.path == path;
        if (!shipped)
            add("URL parameter scene: no scene " + echo(params.scene) + " is shipped");
        else if (!loadScene(app, path))
            add(app.ui.messages.error);
    }
    for (const settings_table::WorldKey* row : params.worldGiven)
        if (const EditError refused =
                app.sim.apply(Edit::setWorld(row->key, settingJson(*row, params.world)));
            !refused.empty())
            add("URL parameter " + refused.text());
    if (params.showGiven) applyShowSet(app.view, params.show);
    if (params.frame) setViewFrame(app.view, *params.frame);
    app.ui.messages.error = errors;
}
