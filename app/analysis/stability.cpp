#include "stability.h"

#include "collision.h"
#include "scene.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace {

std::string format(double v, int precision = 3) {
    std::ostringstream s;
    s << std::setprecision(precision) << v;
    return s.str();
}

// Everything a verdict may need from one run.
struct Run {
    Scene scene;
    World world;
    std::vector<Vec2> start;
    StepTotals totals;
    double maxDisplacement = 0.0; // m, largest distance of a block from its start
    double startEnergy = 0.0;
    double startTotal = 0.0; // J, kinetic + potential at the start
    double maxTotal = 0.0;   // J, the largest kinetic + potential seen at the end of a frame
    double maxSpeed = 0.0;   // m/s, the fastest dynamic block seen at the end of a frame
    bool crossed = false;    // block 0 was seen beyond block 1 along x (tunnelling)
};

Run simulate(const Scene& scene, Method method, double seconds) {
    Run run;
    run.scene = scene;
    run.world = makeWorld(scene);
    run.world.settings.method = method;
    run.startEnergy = kineticEnergy(run.world);
    run.startTotal = run.maxTotal = run.startEnergy + potentialEnergy(run.world);
    for (const Block& b : run.world.blocks) run.start.push_back(b.position);
    const double side = run.world.blocks.size() > 1 ? run.start[1].x - run.start[0].x : 0.0;
    const long frames = std::lround(seconds / scene.settings.dt);
    for (long f = 0; f < frames; ++f) {
        const StepStats s = run.world.step();
        addStep(run.totals, s);
        for (size_t i = 0; i < run.start.size(); ++i) {
            const Block& b = run.world.blocks[i];
            run.maxDisplacement = std::max(run.maxDisplacement, length(b.position - run.start[i]));
            if (b.isDynamic()) run.maxSpeed = std::max(run.maxSpeed, length(b.velocity));
        }
        run.maxTotal = std::max(run.maxTotal, s.kineticEnergy + s.potentialEnergy);
        if (run.world.blocks.size() > 1 &&
            (run.world.blocks[1].position.x - run.world.blocks[0].position.x) * side < 0.0)
            run.crossed = true;
    }
    return run;
}

StabilityResult judge(const std::string& name, const Run& r) {
    StabilityResult out;
    out.scene = name;
    out.friction = r.world.settings.friction;
    out.method = methodName(r.world.settings.method);
    const std::vector<Block>& b = r.world.blocks;
    if (name == "bullet_wall") {
        out.fails = r.crossed;
        out.verdict = r.crossed ? "tunnels" : "stopped";
        out.value = r.crossed;
        out.detail = "bullet seen beyond the wall: " + std::string(r.crossed ? "yes" : "no");
    } else if (name == "resting_stack") {
        out.fails = r.maxDisplacement > 1e-9;
        out.value = r.maxDisplacement;
        out.verdict = out.fails ? "moves " + format(r.maxDisplacement) + " m" : "stable";
        out.detail =
            "largest displacement of a block over 5 s: " + format(r.maxDisplacement) + " m";
    } else if (name == "newtons_cradle") {
        // Exact: only the last block moves, at the striker's speed.
        double error = std::abs(b.back().velocity.x - r.scene.blocks.front().velocity.x);
        for (size_t i = 0; i + 1 < b.size(); ++i) error += length(b[i].velocity);
        out.fails = error > 1e-9;
        out.value = error;
        out.verdict = out.fails ? "spreads (" + format(error) + " m/s off)" : "exact";
        out.detail = "sum of velocity errors against the exact answer: " + format(error) + " m/s";
    } else if (name == "corner_hit") {
        const Vec2 v0 = r.scene.blocks.front().velocity, v = b.front().velocity;
        const bool x = v.x * v0.x < 0.0, y = v.y * v0.y < 0.0;
        out.fails = !(x && y);
        out.value = (x ? 1 : 0) + (y ? 1 : 0);
        out.verdict = x && y ? "both axes" : x ? "x only" : y ? "y only" : "missed";
        out.detail = "velocity components reversed by the corner hit";
    } else if (name == "high_mass_ratio") {
        out.value = static_cast<double>(r.totals.collisions);
        out.fails = r.totals.collisions != 3141 || r.totals.maxPenetration > 1e-9;
        out.verdict = std::to_string(r.totals.collisions) + " collisions";
        if (r.totals.maxPenetration > 1e-9)
            out.verdict += ", overlap " + format(r.totals.maxPenetration) + " m";
        out.detail = "collisions counted (exact: 3141, the digits of pi for a mass ratio of 1e6)";
    } else if (name == "turn_based_dt1_gas" || name == "perfect_edge_1e9") {
        // Energy at the extremes (issue 28): kinetic plus potential energy at the end over the
        // start, as `sandbox-cli run` measures it (it warns above x10); nothing adds any, so any
        // growth beyond rounding (1e-9 relative) is the method's.
        const double end = kineticEnergy(r.world) + potentialEnergy(r.world);
        const double growth = end / r.startTotal;
        out.fails = growth > 1.0 + 1e-9;
        out.value = growth;
        out.verdict = "energy x" + format(growth);
        if (r.totals.eventCapHits > 0)
            out.verdict += ", event cap x" + std::to_string(r.totals.eventCapHits);
        out.detail = "kinetic plus potential energy at the end / start (" + format(r.startTotal) +
                     " J to " + format(end) + " J); fastest block " + format(r.maxSpeed) + " m/s";
    } else if (name == "heavy_on_light" || name == "pile" || name == "crushed_block" ||
               name == "pressed_block") {
        // Nothing may run away: no block faster than 30 m/s (they fall at most 12 m: 15 m/s) and,
        // with C < 1 and no platform, the total energy never above the start (1e-9 relative:
        // rounding of the sums).
        const bool platform = name == "crushed_block" || name == "pressed_block";
        const double growth = r.startTotal > 0.0 ? r.maxTotal / r.startTotal : 1.0;
        const bool gains = !platform && r.maxTotal > r.startTotal + 1e-9 * std::abs(r.startTotal);
        out.fails = r.maxSpeed > 30.0 || gains || r.totals.maxPenetration > 1e-9;
        out.value = r.maxSpeed;
        std::string v;
        if (r.maxSpeed > 30.0) v = "runs away: " + format(r.maxSpeed) + " m/s";
        if (gains) v += std::string(v.empty() ? "" : ", ") + "energy x" + format(growth);
        if (r.totals.maxPenetration > 1e-9)
            v += std::string(v.empty() ? "" : ", ") + "overlap " + format(r.totals.maxPenetration) +
                 " m";
        out.verdict = v.empty() ? "bounded" : v;
        out.detail = "fastest block at a frame's end: " + format(r.maxSpeed) + " m/s" +
                     (platform ? "" : "; largest total energy / start: " + format(growth));
    } else { // inelastic_collapse, jammed_box: the event cap, overlap, energy
        const double drift =
            r.startEnergy > 0.0 ? (kineticEnergy(r.world) - r.startEnergy) / r.startEnergy : 0.0;
        out.fails =
            r.totals.eventCapHits > 0 || r.totals.maxPenetration > 1e-9 || r.maxDisplacement < 1e-9;
        out.value = static_cast<double>(r.totals.eventCapHits);
        std::string v;
        if (r.totals.eventCapHits > 0)
            v = "event cap x" + std::to_string(r.totals.eventCapHits) + ", time behind " +
                format(r.world.frame * r.scene.settings.dt - r.world.time) + " s";
        if (r.totals.maxPenetration > 1e-9)
            v += std::string(v.empty() ? "" : ", ") + "overlap " + format(r.totals.maxPenetration) +
                 " m";
        if (r.maxDisplacement < 1e-9) v = std::string("frozen") + (v.empty() ? "" : ", " + v);
        out.verdict = v.empty() ? "settles" : v;
        out.detail =
            "event-cap hits, simulated time lost, largest overlap; kinetic energy change " +
            format(drift);
    }
    return out;
}

struct FailureScene {
    const char* name; // scene file stem
    double seconds;
    double friction = -1.0; // >= 0: run with the world's friction set to this (a row of its own)
};
const FailureScene kScenes[] = {
    {"bullet_wall", 1.0},    {"resting_stack", 5.0},   {"inelastic_collapse", 2.0},
    {"newtons_cradle", 2.0}, {"corner_hit", 1.5},      {"high_mass_ratio", 20.0},
    {"jammed_box", 1.0},     {"heavy_on_light", 10.0}, {"pile", 10.0},
    {"crushed_block", 10.0}, {"pile", 10.0, 0.5},      {"pressed_block", 10.0},
};

// Energy at the extremes (issue 28): every value valid and at its limit, and a method creates
// energy. Read from the extremes folder (tests/data/extreme), run as `sandbox-cli run` runs them
// in ctest (cli.energy_extreme_*): 600 frames each.
const FailureScene kExtremeScenes[] = {
    {"turn_based_dt1_gas", 600.0}, // dt = 1 s
    {"perfect_edge_1e9", 10.0},    // dt = 1/60 s
};

// The Tips slides' mistakes (WorldSettings::mistakes): each scene is run as shipped, with its
// mistake on, and again with it off; the row says what the mistake changed under each method.
const FailureScene kMistakeScenes[] = {
    {"mistake_discrete", 1.0},
    {"mistake_move_back", 0.5},
    {"mistake_first_found", 1.0},
    {"mistake_no_approach_test", 1.0},
};

StabilityResult judgeMistake(const std::string& name, const Run& on, const Run& off) {
    StabilityResult out;
    out.scene = name;
    out.method = methodName(on.world.settings.method);
    double moved = 0.0; // m, largest difference of a block's final position
    for (size_t i = 0; i < on.world.blocks.size(); ++i)
        moved = std::max(moved, length(on.world.blocks[i].position - off.world.blocks[i].position));
    const long extra = static_cast<long>(on.totals.collisions - off.totals.collisions);
    const double overlap = on.totals.maxPenetration - off.totals.maxPenetration;
    std::string v;
    if (name == "mistake_discrete" && on.crossed != off.crossed) {
        v = on.crossed ? "tunnels" : "stops";
        out.value = 1.0;
    } else if (overlap > 1e-9) {
        v = "overlap " + format(on.totals.maxPenetration) + " m";
        out.value = overlap;
    } else if (extra != 0) {
        v = std::to_string(extra) + " extra collisions";
        out.value = static_cast<double>(extra);
    } else if (moved > 1e-9) {
        v = "crooked: " + format(moved) + " m off";
        out.value = moved;
    }
    out.fails = !v.empty();
    out.verdict = v.empty() ? "unaffected" : v;
    out.detail = "with the mistake against without: tunnelling, extra overlap, extra collisions, "
                 "largest difference of a final position (" +
                 format(moved) + " m)";
    return out;
}

// Why each method does what it does, for the rows friction (issue 25) and the energy extremes
// (issue 28) added; written under the matrix. The measured figures are the matrix's and the CSV's.
struct Reason {
    const char* row; // rowName()
    const char* why;
};
const Reason kReasons[] = {
    {"pile (friction 0.5)",
     "friction only slows the sliding of two faces toward each other's velocity, by at most mu "
     "times the contact's own change across the face (friction.cpp), so it takes energy and never "
     "gives any: perfect and turn-based stay bounded with the total energy never above the start, "
     "as without friction; move-and-correct still moves before it corrects, and overlaps."},
    {"pressed_block (friction 0.5)",
     "perfect meets the platform at the instant of contact and resolves the crush (the crate "
     "cannot give way: the platform turns around), and the crate never moves; turn-based gives "
     "the crate, in the crush's frame, the platform's friction bounded by the g·dt the contact "
     "absorbed, mu·g·dt (the 0.0818 m/s in the CSV), which the floor's friction takes back the "
     "next frame; move-and-correct moves the platform into the crate first, and the correction "
     "shoves the crate aside."},
    {"turn_based_dt1_gas",
     "turn-based loses the rest of a block's frame at each bounce after the frame's g·dt was "
     "added, so with C = 1 every bounce can gain up to m·g·h·|v| (README, method table): at "
     "dt = 1 s that is 9.81 m/s a bounce; perfect gains by semi-implicit Euler at dt = 1 s "
     "(v += g·dt before the move; the exact integrator keeps it); move-and-correct's corrections "
     "take energy out instead."},
    {"perfect_edge_1e9",
     "the light blocks meet the 1e15 kg block more often than the event cap allows in a frame: "
     "each capped frame ends at its last event with gravity's g·dt already added, so time falls "
     "behind while velocity does not; move-and-correct and turn-based never hold time back (their "
     "frames always end at the frame's end) and lose energy here."},
};

Scene loadScene(const std::string& scenesDir, const char* name) {
    SceneResult loaded = loadSceneFile(scenesDir + "/" + name + ".json");
    if (!loaded.scene) throw std::runtime_error(loaded.error.text());
    return *loaded.scene;
}

} // namespace

std::vector<StabilityResult> runStability(const std::string& scenesDir,
                                          const std::string& extremesDir,
                                          const std::vector<std::string>& only) {
    std::vector<StabilityResult> results;
    auto wanted = [&](const char* name) {
        return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
    };
    auto runRows = [&](const std::string& dir, const FailureScene& fs) {
        if (!wanted(fs.name)) return;
        Scene scene = loadScene(dir, fs.name);
        if (fs.friction >= 0.0) scene.settings.friction = fs.friction;
        for (int m = 0; m < static_cast<int>(Method::Count); ++m)
            results.push_back(judge(fs.name, simulate(scene, static_cast<Method>(m), fs.seconds)));
    };
    for (const FailureScene& fs : kScenes) runRows(scenesDir, fs);
    if (!extremesDir.empty())
        for (const FailureScene& fs : kExtremeScenes) runRows(extremesDir, fs);
    for (const FailureScene& fs : kMistakeScenes) {
        if (!wanted(fs.name)) continue;
        const Scene scene = loadScene(scenesDir, fs.name);
        Scene correct = scene;
        correct.settings.mistakes = 0;
        for (int m = 0; m < static_cast<int>(Method::Count); ++m) {
            const Method method = static_cast<Method>(m);
            results.push_back(judgeMistake(fs.name, simulate(scene, method, fs.seconds),
                                           simulate(correct, method, fs.seconds)));
        }
    }
    return results;
}

std::string rowName(const StabilityResult& r) {
    return r.friction > 0.0 ? r.scene + " (friction " + format(r.friction) + ")" : r.scene;
}

void writeStabilityCsv(std::ostream& out, const std::vector<StabilityResult>& results) {
    out << "scene,method,verdict,fails,value,detail\n" << std::setprecision(9);
    for (const StabilityResult& r : results)
        out << rowName(r) << ',' << r.method << ",\"" << r.verdict << "\"," << (r.fails ? 1 : 0)
            << ',' << r.value << ",\"" << r.detail << "\"\n";
}

void writeStabilityMarkdown(std::ostream& out, const std::vector<StabilityResult>& results) {
    out << "| scene |";
    for (int m = 0; m < static_cast<int>(Method::Count); ++m)
        out << ' ' << methodName(static_cast<Method>(m)) << " |";
    out << "\n|---|---|---|---|\n";
    for (size_t i = 0; i < results.size(); i += static_cast<size_t>(Method::Count)) {
        out << "| " << rowName(results[i]) << " |";
        for (int m = 0; m < static_cast<int>(Method::Count); ++m) {
            const StabilityResult& r = results[i + m];
            out << ' ' << (r.fails ? "**" + r.verdict + "**" : r.verdict) << " |";
        }
        out << '\n';
    }
    out << "\nBold: the method shows the scene's failure.\n";
    bool heading = false;
    for (const Reason& reason : kReasons) {
        const bool shown = std::any_of(results.begin(), results.end(),
                                       [&](const auto& r) { return rowName(r) == reason.row; });
        if (!shown) continue;
        if (!heading) out << "\nWhy, for the rows of friction and of energy at the extremes:\n\n";
        heading = true;
        out << "- " << reason.row << ": " << reason.why << '\n';
    }
}
