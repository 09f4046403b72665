// sandbox-cli run and validate (SPEC.md, "Command-line contract").
#include "commands.h"

#include "lesson_runner.h"
#include "scene.h"
#include "world.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <ostream>

namespace {

// ---- Option values: strict parsing (the whole text, finite numbers) ----

bool parseDouble(const std::string& text, double& value) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(x)) return false;
    value = x;
    return true;
}

bool parseInt(const std::string& text, std::int64_t& value) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    const long long x = std::strtoll(text.c_str(), &end, 10);
    if (end != text.c_str() + text.size() || errno == ERANGE) return false;
    value = x;
    return true;
}

// How long to run: a number of frames, or until a simulated time.
struct StopRule {
    std::int64_t frames = kDefaultSteps; // the frame limit (for --time: the event-cap backstop)
    std::optional<double> time;          // s, with --time
};

// Applies the command-line overrides to the scene's settings. Returns false and writes a message
// naming the option on a bad value.
bool applyOptions(const RunRequest& r, WorldSettings& s, StopRule& stop, std::ostream& err) {
    auto bad = [&](const char* option, const std::string& value, const char* expected) {
        err << "sandbox-cli run: " << option << " " << value << ": " << expected << "\n";
        return false;
    };
    if (r.method && !parseMethod(r.method->c_str(), s.method))
        return bad("--method", *r.method, "must be perfect, move-and-correct or turn-based");
    if (r.dt && !(parseDouble(*r.dt, s.dt) && s.dt > 0.0 && s.dt <= 1.0))
        return bad("--dt", *r.dt, "must be a number of seconds more than 0 and at most 1");
    if (r.substeps) {
        std::int64_t k = 0;
        if (!parseInt(*r.substeps, k) || k < 1 || k > 1000)
            return bad("--substeps", *r.substeps, "must be a whole number from 1 to 1000");
        s.substeps = static_cast<int>(k);
    }
    if (r.bounciness &&
        !(parseDouble(*r.bounciness, s.bounciness) && s.bounciness >= 0.0 && s.bounciness <= 1.0))
        return bad("--bounciness", *r.bounciness, "must be a number from 0 to 1");
    if (r.gravity) {
        const std::size_t comma = r.gravity->find(',');
        Vec2 g;
        if (comma == std::string::npos || !parseDouble(r.gravity->substr(0, comma), g.x) ||
            !parseDouble(r.gravity->substr(comma + 1), g.y))
            return bad("--gravity", *r.gravity, "must be GX,GY in m/s^2, e.g. 0,-9.81");
        s.gravity = g;
    }
    if (r.resolve && !parseResolve(r.resolve->c_str(), s.resolve))
        return bad("--resolve", *r.resolve, "must be momentum or reflect");
    if (r.integrator && !parseIntegrator(r.integrator->c_str(), s.integrator))
        return bad("--integrator", *r.integrator,
                   "must be semi-implicit-euler, explicit-euler or exact");
    for (const std::string& name : r.mistakes) {
        if (name == "none") { // the scene's mistakes off
            s.mistakes = 0;
            continue;
        }
        Mistake m{};
        if (!parseMistake(name.c_str(), m))
            return bad("--mistake", name,
                       "must be discrete, move-back, first-found, no-approach-test or none");
        s.set(m, true);
    }
    if (r.steps && !(parseInt(*r.steps, stop.frames) && stop.frames >= 0))
        return bad("--steps", *r.steps, "must be a whole number of frames, 0 or more");
    if (r.time) {
        double t = 0.0;
        if (!parseDouble(*r.time, t) || t < 0.0)
            return bad("--time", *r.time, "must be a number of seconds, 0 or more");
        const double backstop = std::ceil(100.0 * t / s.dt);
        if (backstop > 1e15) return bad("--time", *r.time, "is too long for this dt");
        stop.time = t;
        stop.frames = static_cast<std::int64_t>(backstop);
    }
    return true;
}

// ---- --trace: one CSV row per frame, for a spreadsheet ----

// A CSV field: quoted, quotes doubled, control bytes (never echoed raw) as spaces.
std::string csvField(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"')
            out += "\"\"";
        else
            out += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? ' ' : c;
    }
    return out + "\"";
}

void writeTraceHeader(std::ostream& out, const Scene& scene) {
    out << "t";
    for (std::size_t i = 0; i < scene.blocks.size(); ++i) {
        const std::string name = scene.blocks[i].name.empty() ? "blocks[" + std::to_string(i) + "]"
                                                              : scene.blocks[i].name;
        for (const char* column : {" x", " y", " vx", " vy"}) out << ',' << csvField(name + column);
    }
    out << ",momentum_x,momentum_y,kinetic_energy,potential_energy\n";
}

// t (s), per block position (m) and velocity (m/s), totals: momentum (kg m/s), energies (J).
void writeTraceRow(std::ostream& out, const World& world, const StepStats& s) {
    out << world.time;
    for (const Block& b : world.blocks)
        out << ',' << b.position.x << ',' << b.position.y << ',' << b.velocity.x << ','
            << b.velocity.y;
    out << ',' << s.momentum.x << ',' << s.momentum.y << ',' << s.kineticEnergy << ','
        << s.potentialEnergy << '\n';
}

StepTotals simulate(World& world, const StopRule& stop, std::ostream* trace) {
    StepTotals totals;
    // --time stops once the world time is within a tiny fraction of a frame of T, so rounding in
    // the sum of the frame lengths cannot add a frame.
    const double epsilon = 1e-6 * world.settings.dt;
    while (totals.steps < stop.frames) {
        if (stop.time && world.time >= *stop.time - epsilon) break;
        const StepStats s = world.step();
        if (trace) writeTraceRow(*trace, world, s);
        addStep(totals, s);
    }
    return totals;
}

nlohmann::ordered_json vecJson(Vec2 v) {
    return {v.x, v.y};
}

void printJson(const Scene& scene, const World& world, const StepTotals& t, std::ostream& out) {
    nlohmann::ordered_json j;
    const WorldSettings& s = world.settings;
    j["scene"] = scene.name;
    j["method"] = methodName(s.method);
    j["dt"] = s.dt;
    j["substeps"] = s.substeps;
    j["bounciness"] = s.bounciness;
    j["gravity"] = vecJson(s.gravity);
    j["resolve"] = resolveName(s.resolve);
    j["integrator"] = integratorName(s.integrator);
    nlohmann::ordered_json mistakes = nlohmann::ordered_json::array();
    for (int m = 0; m < static_cast<int>(Mistake::Count); ++m)
        if (s.has(static_cast<Mistake>(m)))
            mistakes.push_back(mistakeName(static_cast<Mistake>(m)));
    j["mistakes"] = std::move(mistakes);
    j["drag"] = s.drag;
    j["sim_time"] = world.time;
    j["steps"] = t.steps;
    j["collisions"] = t.collisions;
    j["max_penetration"] = t.maxPenetration;
    j["momentum"] = vecJson(totalMomentum(world));
    j["kinetic_energy"] = kineticEnergy(world);
    j["potential_energy"] = potentialEnergy(world);
    j["event_cap_hits"] = t.eventCapHits;
    j["wall_ms"] = t.stepMs; // inside World::step only
    nlohmann::ordered_json blocks = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < world.blocks.size(); ++i) {
        nlohmann::ordered_json b;
        b["name"] = i < scene.blocks.size() ? scene.blocks[i].name : std::string();
        b["position"] = vecJson(world.blocks[i].position);
        b["velocity"] = vecJson(world.blocks[i].velocity);
        blocks.push_back(std::move(b));
    }
    j["blocks"] = std::move(blocks);
    out << j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
}

std::ostream& operator<<(std::ostream& out, Vec2 v) {
    return out << "(" << v.x << ", " << v.y << ")";
}

void printText(const Scene& scene, const World& world, const StepTotals& t, std::ostream& out) {
    const WorldSettings& s = world.settings;
    const std::ios::fmtflags flags = out.flags();
    const std::streamsize precision = out.precision(6);
    out << "scene             " << scene.name << "\n"
        << "method            " << methodName(s.method) << "  (dt " << s.dt << " s, " << s.substeps
        << (s.substeps == 1 ? " substep" : " substeps") << ", bounciness " << s.bounciness
        << ", gravity " << s.gravity << " m/s^2)\n"
        << "steps             " << t.steps << "  (" << world.time << " s simulated)\n"
        << "collisions        " << t.collisions << "\n"
        << "momentum          " << totalMomentum(world) << " kg m/s\n"
        << "kinetic energy    " << kineticEnergy(world) << " J\n"
        << "potential energy  " << potentialEnergy(world) << " J\n"
        << "max penetration   " << t.maxPenetration << " m\n"
        << "event-cap hits    " << t.eventCapHits << "\n"
        << "wall time         " << std::fixed << std::setprecision(3) << t.stepMs
        << " ms in steps\n";
    out.flags(flags);
    out.precision(6);
    if (world.blocks.size() <= 20) {
        for (std::size_t i = 0; i < world.blocks.size(); ++i) {
            const std::string& name = scene.blocks[i].name;
            out << "  " << std::left << std::setw(16)
                << (name.empty() ? "blocks[" + std::to_string(i) + "]" : name) << std::right
                << " position " << world.blocks[i].position << "  velocity "
                << world.blocks[i].velocity << "\n";
        }
    } else {
        out << "  (" << world.blocks.size() << " blocks; use --json for every block)\n";
    }
    out.flags(flags);
    out.precision(precision);
}

} // namespace

int runCommand(const RunRequest& request, std::ostream& out, std::ostream& err) {
    const SceneResult loaded = loadSceneFile(request.scene);
    if (!loaded.scene) {
        err << loaded.error.text() << "\n";
        return kExitBadInput;
    }
    Scene scene = *loaded.scene;
    StopRule stop;
    if (!applyOptions(request, scene.settings, stop, err)) return kExitBadInput;
    World world = makeWorld(scene);
    std::ofstream trace;
    if (request.trace) {
        trace.open(*request.trace, std::ios::binary | std::ios::trunc);
        if (!trace) {
            err << "sandbox-cli run: --trace " << *request.trace << ": cannot write the file\n";
            return kExitBadInput;
        }
        trace << std::setprecision(17);
        writeTraceHeader(trace, scene);
    }
    const StepTotals totals = simulate(world, stop, request.trace ? &trace : nullptr);
    if (request.trace) {
        trace.close();
        if (!trace) {
            err << "sandbox-cli run: --trace " << *request.trace << ": writing failed\n";
            return kExitBadInput;
        }
    }
    if (request.json)
        printJson(scene, world, totals, out);
    else
        printText(scene, world, totals, out);
    return kExitOk;
}

int validateCommand(const std::string& path, std::ostream& out, std::ostream& err,
                    const LessonContext& lessons) {
    if (isLessonFile(path)) {
        const LessonResult lesson = loadLessonFile(path, lessons);
        if (!lesson.lesson) {
            err << lesson.error.text() << "\n";
            return kExitBadInput;
        }
        const std::vector<std::string> failures = checkLesson(*lesson.lesson);
        for (const std::string& f : failures) err << f << "\n";
        if (!failures.empty()) return kExitBadInput;
        out << "ok\n";
        return kExitOk;
    }
    const SceneResult loaded = loadSceneFile(path);
    if (!loaded.scene) {
        err << loaded.error.text() << "\n";
        return kExitBadInput;
    }
    out << "ok\n";
    return kExitOk;
}

int lessonCommand(const std::string& path, std::ostream& out, std::ostream& err,
                  const LessonContext& lessons) {
    const LessonResult loaded = loadLessonFile(path, lessons);
    if (!loaded.lesson) {
        err << loaded.error.text() << "\n";
        return kExitBadInput;
    }
    const Lesson& lesson = *loaded.lesson;
    out << lesson.name << ": " << lesson.steps.size() << " steps\n";
    std::vector<std::string> failures;
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& step = lesson.steps[i];
        const StepRun run = runStepToPause(step);
        out << i + 1 << ". " << step.title << ": " << (run.reached ? "paused" : "NOT PAUSED")
            << " at t = " << run.world.time << " s (frame " << run.progress.frames << "), "
            << run.progress.collisions << " collisions, " << methodName(run.world.settings.method)
            << "\n";
        for (std::size_t b = 0; b < run.world.blocks.size() && b < 12; ++b) {
            const Block& block = run.world.blocks[b];
            out << "     " << std::left << std::setw(14)
                << (step.scene.blocks[b].name.empty() ? "#" + std::to_string(b)
                                                      : step.scene.blocks[b].name)
                << std::right << " position " << block.position << "  velocity " << block.velocity
                << "\n";
        }
        const std::vector<std::string> f = checkStep(step, run);
        failures.insert(failures.end(), f.begin(), f.end());
    }
    for (const std::string& f : failures) err << f << "\n";
    return failures.empty() ? kExitOk : kExitBadInput;
}
