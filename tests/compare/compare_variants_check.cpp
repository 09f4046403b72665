// sandbox-cli compare diagnoses each variant of the reference as itself (issue 29, "Done when"):
// for every method and every change (each mistake, the other resolve, each other integrator), a
// trace made with `sandbox-cli run --trace` from that variant is compared with the scene's
// reference; the diagnosis names that variant (or one that simulates the same bit for bit), and
// the reference's own trace compares equal, in SI and in gxp units (converted here).
//   compare_variants_check SANDBOX_CLI SCENES_DIR WORK_DIR SCENE [MUST_DIFFER...]
// MUST_DIFFER: variants ("method turn-based", "mistake move-back", ...) that differ from the
// reference on this scene, so their trace must compare different.
#include "../cli/cli_check.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using cli_check::capture;
using cli_check::check;
using nlohmann::json;

namespace {

struct Source {
    std::string label;   // "method turn-based + mistake move-back"
    std::string options; // sandbox-cli run options
    json settings;       // {method, mistakes, resolve, integrator}
};

int exitCode(int status) {
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool sameSettings(const json& a, const json& b) {
    return a["method"] == b["method"] && a["mistakes"] == b["mistakes"] &&
           a["resolve"] == b["resolve"] && a["integrator"] == b["integrator"];
}

// Whether the diagnosis names `source`: the best variant, one that simulates the same bit for
// bit, or one as close (the same largest error).
bool diagnosedAs(const json& diagnosis, const json& settings) {
    const json& best = diagnosis["variant"];
    if (best.is_null()) return false;
    auto names = [&](const json& fit) {
        if (sameSettings(fit["settings"], settings)) return true;
        for (const json& twin : fit["same_as"])
            if (sameSettings(twin["settings"], settings)) return true;
        return false;
    };
    if (names(best)) return true;
    for (const json& also : diagnosis["also"])
        if (also["max_position_error"] == best["max_position_error"] && names(also)) return true;
    return false;
}

// The trace converted to gxp: pixels (50 px/m, the world's top-left corner at pixel (40, 30)),
// y down, velocities in pixels per frame; semicolons and decimal commas.
void writeGxp(const std::string& from, const std::string& to, double dt, double top, double left) {
    std::ifstream in(from);
    std::ofstream out(to);
    std::string line;
    std::getline(in, line);
    out << "t";
    std::vector<std::string> names;
    std::stringstream header(line);
    std::string field;
    std::getline(header, field, ','); // t
    while (std::getline(header, field, ',')) {
        if (field.front() == '"') field = field.substr(1, field.size() - 2);
        names.push_back(field);
    }
    const std::size_t blockColumns = names.size() - 4; // momentum and energies last
    for (std::size_t c = 0; c < blockColumns; ++c) {
        std::string n = names[c];
        n[n.rfind(' ')] = '_';
        out << ";" << n;
    }
    out << "\n" << std::setprecision(9);
    const double k = 50.0, ox = 40.0, oy = 30.0;
    while (std::getline(in, line)) {
        std::stringstream row(line);
        std::vector<double> v;
        while (std::getline(row, field, ',')) v.push_back(std::stod(field));
        std::ostringstream text;
        text << std::setprecision(9) << v[0];
        for (std::size_t c = 0; c < blockColumns; ++c) {
            const double x = v[1 + c];
            double px = 0.0;
            switch (c % 4) {
            case 0:
                px = ox + (x - left) * k;
                break;
            case 1:
                px = oy + (top - x) * k;
                break;
            case 2:
                px = x * k * dt;
                break;
            case 3:
                px = -x * k * dt;
                break;
            }
            text << ";" << static_cast<float>(px); // single precision, as a C# engine prints
        }
        std::string s = text.str();
        std::replace(s.begin(), s.end(), '.', ',');
        out << s << "\n";
    }
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 5) {
        std::cerr << "usage: compare_variants_check SANDBOX_CLI SCENES_DIR WORK_DIR SCENE "
                     "[MUST_DIFFER...]\n";
        return 2;
    }
    const std::string cli = argv[1], scenes = argv[2], work = argv[3], name = argv[4];
    const std::set<std::string> mustDiffer(argv + 5, argv + argc);
    const std::string scene = scenes + "/" + name + ".json";
    int status = 0;
    const json plain =
        json::parse(capture(cli + " run " + scene + " --steps 0 --json", status), nullptr, false);
    if (plain.is_discarded()) {
        std::cerr << "FAILED: " << name << ": run --json\n";
        return 1;
    }
    const std::string method = plain["method"], resolve = plain["resolve"],
                      integrator = plain["integrator"];

    std::vector<Source> sources;
    for (const char* m : {"perfect", "move-and-correct", "turn-based"}) {
        const std::string base = m == method ? "" : std::string("method ") + m;
        json settings = {{"method", m},
                         {"mistakes", json::array()},
                         {"resolve", resolve},
                         {"integrator", integrator}};
        sources.push_back(
            {base.empty() ? "the reference" : base, std::string("--method ") + m, settings});
        auto plus = [&](const std::string& change) {
            return base.empty() ? change : base + " + " + change;
        };
        for (const char* mistake : {"discrete", "move-back", "first-found", "no-approach-test"}) {
            json s = settings;
            s["mistakes"] = json::array({mistake});
            sources.push_back({plus(std::string("mistake ") + mistake),
                               std::string("--method ") + m + " --mistake " + mistake, s});
        }
        const std::string otherResolve = resolve == "momentum" ? "reflect" : "momentum";
        json r = settings;
        r["resolve"] = otherResolve;
        sources.push_back({plus("resolve " + otherResolve),
                           std::string("--method ") + m + " --resolve " + otherResolve, r});
        for (const char* i : {"semi-implicit-euler", "explicit-euler", "exact"}) {
            if (i == integrator) continue;
            json s = settings;
            s["integrator"] = i;
            sources.push_back({plus(std::string("integrator ") + i),
                               std::string("--method ") + m + " --integrator " + i, s});
        }
    }

    int differing = 0;
    std::set<std::string> differed;
    for (const Source& source : sources) {
        const std::string trace = work + "/" + name + "_trace.csv";
        capture(cli + " run " + scene + " --mistake none " + source.options + " --trace " + trace,
                status);
        check(exitCode(status) == 0, name + " " + source.label + ": run --trace");
        const std::string out =
            capture(cli + " compare " + scene + " " + trace + " --json", status);
        const int code = exitCode(status);
        const json j = json::parse(out, nullptr, false);
        const std::string what = name + ", a trace of " + source.label;
        if (j.is_discarded()) {
            check(false, what + ": compare --json prints JSON (exit " + std::to_string(code) + ")");
            continue;
        }
        if (source.label == "the reference") {
            check(code == 0 && j["result"] == "same", what + ": compares equal (exit 0)");
            // The same trace in gxp units, single precision, semicolons and decimal commas.
            const json bounds = j["reference"];
            const std::string gxp = work + "/" + name + "_trace_gxp.csv";
            const json sceneJson = json::parse(std::ifstream(scene));
            writeGxp(trace, gxp, j["reference"]["dt"], sceneJson["world"]["bounds"][3],
                     sceneJson["world"]["bounds"][0]);
            capture(cli + " compare " + scene + " " + gxp +
                        " --units gxp --px-per-m 50 --px-origin 40,30",
                    status);
            check(exitCode(status) == 0, what + " in gxp units: compares equal (exit 0)");
            continue;
        }
        if (code == 0) {
            check(!mustDiffer.count(source.label), what + ": must differ from the reference");
            continue;
        }
        ++differing;
        differed.insert(source.label);
        check(code == 3 && j["result"] == "different", what + ": exit 3 and different");
        check(diagnosedAs(j["diagnosis"], source.settings),
              what + ": diagnosed as " + source.label + ", not " +
                  (j["diagnosis"]["variant"].is_null()
                       ? std::string("nothing")
                       : j["diagnosis"]["variant"]["name"].get<std::string>()));
    }
    for (const std::string& label : mustDiffer)
        check(differed.count(label) > 0,
              name + ": " + label + " must be among the variants that differ");
    std::cout << name << ": " << sources.size() << " variants, " << differing
              << " differ from the reference, " << cli_check::failures << " failures\n";
    return cli_check::failures == 0 ? 0 : 1;
}
