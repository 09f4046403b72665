// Issue 16's "Done when", checked the way tests outside the project do it: through
// `sandbox-cli run --json` (and --trace). Usage: cli_lecture_check SANDBOX_CLI SCENES_DIR TMP_DIR.
#include "cli_check.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using cli_check::capture;
using cli_check::check;

nlohmann::json run(const std::string& cli, const std::string& scene, const std::string& options) {
    int status = -1;
    const std::string out = capture("'" + cli + "' run '" + scene + "' --json " + options, status);
    check(status == 0, scene + " " + options + ": exit status 0");
    try {
        return nlohmann::json::parse(out);
    } catch (const std::exception& e) {
        check(false, scene + " " + options + ": JSON output");
        return nlohmann::json::object();
    }
}

double num(const nlohmann::json& j) {
    return j.is_number() ? j.get<double>() : NAN;
}

void writeFile(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

// The rows of a CSV file written by --trace, split at commas (the numbers have none).
std::vector<std::vector<std::string>> readCsv(const std::string& path) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::stringstream s(line);
        std::string cell;
        while (std::getline(s, cell, ',')) cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: cli_lecture_check SANDBOX_CLI SCENES_DIR TMP_DIR\n";
        return 2;
    }
    const std::string cli = argv[1], dir = std::string(argv[2]) + "/", tmp = std::string(argv[3]);

    // --resolve reflect on lecture_example_1: m1 leaves at -6 m/s, m2 stays at rest.
    for (const char* method : {"perfect", "move-and-correct", "turn-based"}) {
        const nlohmann::json j = run(cli, dir + "lecture_example_1.json",
                                     std::string("--time 1 --resolve reflect --method ") + method);
        check(num(j["blocks"][0]["velocity"][0]) == -6.0, std::string(method) + ": reflect v1 -6");
        check(num(j["blocks"][1]["velocity"][0]) == 0.0, std::string(method) + ": reflect v2 0");
    }

    // --integrator exact, perfect, dt 1/60: after n bounces the apex y + vy²/(2g) is h·C^(2n)
    // within 1e-6 relative (bounce_exact: h = 4 m, C = 0.8), and the block is at rest from the
    // frame that contains sqrt(2h/g)(1+C)/(1-C) on.
    {
        const double h = 4.0, C = 0.8, g = 9.81, dt = 1.0 / 60.0;
        std::vector<double> impacts{std::sqrt(2.0 * h / g)};
        double v = std::sqrt(2.0 * g * h);
        for (int k = 0; k < 200; ++k) impacts.push_back(impacts.back() + 2.0 * (v *= C) / g);
        const double rest = std::sqrt(2.0 * h / g) * (1.0 + C) / (1.0 - C);
        for (int steps = 30; steps < rest / dt; steps += 23) {
            const nlohmann::json j =
                run(cli, dir + "bounce_exact.json",
                    "--integrator exact --method perfect --steps " + std::to_string(steps));
            const double t = num(j["sim_time"]);
            int n = 0;
            while (impacts[n] < t) ++n;
            const double y = num(j["blocks"][0]["position"][1]) - 0.5;
            const double vy = num(j["blocks"][0]["velocity"][1]);
            const double expected = h * std::pow(C, 2.0 * n);
            if (expected < 1e-3) break; // the last bounces are shorter than a frame
            check(std::abs((y + vy * vy / (2.0 * g)) / expected - 1.0) < 1e-6,
                  "exact: apex after " + std::to_string(n) +
                      " bounces at t = " + std::to_string(t));
        }
        const nlohmann::json after = run(cli, dir + "bounce_exact.json",
                                         "--steps " + std::to_string(int(std::ceil(rest / dt))));
        check(num(after["blocks"][0]["velocity"][1]) == 0.0 &&
                  num(after["blocks"][0]["position"][1]) == 0.5,
              "exact: at rest at the end of the frame containing the time to rest");
        const nlohmann::json before =
            run(cli, dir + "bounce_exact.json",
                "--steps " + std::to_string(int(std::floor(rest / dt)) - 1));
        check(num(before["blocks"][0]["position"][1]) > 0.5,
              "exact: still bouncing a frame before");
    }

    // "force": [2, 0] on 4 kg without gravity: vx = 0.5·t exactly in every method.
    const std::string thrust = tmp + "/lecture_thrust.json";
    writeFile(thrust, R"({"name": "thrust", "world": {"gravity": [0, 0], "bounds": [0, 0, 100, 12]},
        "blocks": [{"name": "ship", "position": [2, 6], "size": 1, "mass": 4, "force": [2, 0]}]})");
    for (const char* method : {"perfect", "move-and-correct", "turn-based"}) {
        const nlohmann::json j = run(cli, thrust, std::string("--time 5 --method ") + method);
        check(num(j["blocks"][0]["velocity"][0]) == 0.5 * num(j["sim_time"]),
              std::string(method) + ": vx = 0.5 t exactly");
    }

    // "drag": a falling block reaches sqrt(m·g/(k·A)) within 1e-3 relative.
    const std::string drag = tmp + "/lecture_drag.json";
    writeFile(drag, R"({"name": "drag", "world": {"drag": 1.2, "bounds": [0, 0, 10, 200]},
        "blocks": [{"name": "b", "position": [5, 190], "size": 0.5, "mass": 1}]})");
    for (const char* integrator : {"semi-implicit-euler", "explicit-euler", "exact"}) {
        const nlohmann::json j =
            run(cli, drag, std::string("--time 10 --integrator ") + integrator);
        const double terminal = std::sqrt(1.0 * 9.81 / (1.2 * 0.25));
        check(std::abs(-num(j["blocks"][0]["velocity"][1]) / terminal - 1.0) < 1e-3,
              std::string(integrator) + ": terminal speed");
    }

    // --friction (issue 25): a block launched at 5 m/s on the floor stops v0²/(2·µ·g) m on, to
    // 1e-9 with the perfect method and the exact integrator (the motion is a parabola up to the
    // stop, an event; --json prints 17 significant digits), within one frame's travel (v0·dt)
    // with semi-implicit Euler (friction acts once per substep). The flag overrides the scene's
    // "friction" 0; the second block's own "friction" 0.125 mixes with the floor's 0.5 as
    // sqrt(0.5·0.125) = 0.25 (Box2D's rule).
    const std::string slide = tmp + "/lecture_friction.json";
    writeFile(slide, R"({"name": "slide", "world": {"friction": 0, "bounds": [0, 0, 40, 12]},
        "blocks": [{"name": "b", "position": [2, 0.5], "size": 1, "velocity": [5, 0]},
                   {"name": "own", "position": [20, 0.5], "size": 1, "velocity": [5, 0],
                    "friction": 0.125}]})");
    for (const char* integrator : {"exact", "semi-implicit-euler"}) {
        const nlohmann::json j =
            run(cli, slide,
                std::string("--time 3 --friction 0.5 --method perfect --integrator ") + integrator);
        const double tolerance = std::string(integrator) == "exact" ? 1e-9 : 5.0 / 60.0;
        const std::string what = std::string(integrator) + ": ";
        for (int b : {0, 1}) {
            const double mu = b == 0 ? 0.5 : 0.25, x0 = b == 0 ? 2.0 : 20.0;
            const double stop = x0 + 25.0 / (2.0 * mu * 9.81);
            check(std::abs(num(j["blocks"][b]["position"][0]) - stop) < tolerance,
                  what + "stops at v0^2/(2 mu g), mu " + std::to_string(mu));
            check(num(j["blocks"][b]["velocity"][0]) == 0.0, what + "at rest by 3 s");
        }
        check(num(j["friction"]) == 0.5, what + "--json says friction 0.5");
    }

    // --mistake discrete: bullet_wall tunnels under turn-based and perfect; without, neither.
    const std::string trace = tmp + "/lecture_trace.csv";
    for (const char* method : {"perfect", "turn-based"}) {
        for (const bool discrete : {false, true}) {
            run(cli, dir + "bullet_wall.json",
                std::string("--time 1 --method ") + method + " --trace '" + trace + "'" +
                    (discrete ? " --mistake discrete" : ""));
            bool beyond = false;
            const auto rows = readCsv(trace);
            for (std::size_t r = 1; r < rows.size(); ++r)
                beyond |= rows[r].size() > 5 && std::stod(rows[r][1]) > std::stod(rows[r][5]);
            check(beyond == discrete, std::string(method) + (discrete ? ": tunnels with discrete"
                                                                      : ": stops without it"));
        }
    }

    // --trace on lecture_example_1: a header and one row per frame; momentum constant (3 s: the
    // collision at 0.625 s, before m2 reaches the wall at 3.3 s).
    run(cli, dir + "lecture_example_1.json", "--steps 180 --trace '" + trace + "'");
    const auto rows = readCsv(trace);
    check(rows.size() == 181, "trace: header and 180 rows");
    if (!rows.empty()) {
        std::size_t column = 0;
        while (column < rows[0].size() && rows[0][column] != "momentum_x") ++column;
        check(column < rows[0].size(), "trace: a momentum_x column");
        for (std::size_t r = 1; r < rows.size() && column < rows[0].size(); ++r)
            check(rows[r].size() == rows[0].size() && std::stod(rows[r][column]) == 6.0,
                  "trace: momentum 6 in row " + std::to_string(r));
    }

    // Without --steps or --time the scene's "duration" (3 s) is the run's length: the same rows,
    // so the plain `run lecture_example_1.json --trace FILE` shows momentum conserved.
    run(cli, dir + "lecture_example_1.json", "--trace '" + trace + "'");
    const auto plain = readCsv(trace);
    check(plain == rows, "trace without --steps: the scene's 3 s, the same 180 rows");

    if (cli_check::failures == 0) std::cout << "all checks passed\n";
    return cli_check::failures == 0 ? 0 : 1;
}
