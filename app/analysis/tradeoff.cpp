#include "tradeoff.h"

#include "chart.h"
#include "peers.h"
#include "simulation.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <stdexcept>

namespace {

// An error measure: sees every frame, then gives one number.
class Measure {
  public:
    virtual ~Measure() = default;
    virtual void observe(Simulation&) {}
    virtual double finish(Simulation& sim) = 0;
};

// A block dropped onto the floor: after n bounces its energy is C^(2n) of the start (lecture,
// "Bounce elasticity"). Measured at the exact apex after the third bounce, as a relative error.
class BounceEnergy : public Measure {
  public:
    BounceEnergy(const Scene& s) : g_(-s.settings.gravity.y), C_(s.settings.bounciness) {
        const BlockDef& b = s.blocks.at(0);
        restY_ = s.bounds.min.y + b.size.y / 2;
        const double drop = b.position.y - restY_;
        const double t1 = std::sqrt(2 * drop / g_), v1 = g_ * t1;
        duration = t1 + 2 * C_ * v1 / g_ + 2 * C_ * C_ * v1 / g_ + C_ * C_ * C_ * v1 / g_;
        startEnergy_ = g_ * drop; // per kg
    }
    double finish(Simulation& sim) override {
        const Block& b = sim.blocks().at(0);
        const double energy = 0.5 * lengthSquared(b.velocity) + g_ * (b.position.y - restY_);
        return std::abs(energy - std::pow(C_, 6) * startEnergy_) / startEnergy_;
    }
    double duration = 0.0;

  private:
    double g_, C_, restY_ = 0.0, startEnergy_ = 0.0;
};

// Largest distance (m) of any block from where the exact solution puts it at the end.
class FinalPositions : public Measure {
  public:
    explicit FinalPositions(std::vector<Vec2> exact) : exact_(std::move(exact)) {}
    double finish(Simulation& sim) override {
        double worst = 0.0;
        for (size_t i = 0; i < exact_.size(); ++i)
            worst = std::max(worst, length(sim.blocks()[i].position - exact_[i]));
        return worst;
    }

  private:
    std::vector<Vec2> exact_;
};

// An elastic gas: relative drift of kinetic energy, or the largest overlap relative to the block
// size, whichever is worse.
class GasDrift : public Measure {
  public:
    GasDrift(const Scene& s) : size_(s.blocks.at(0).size.x) {
        for (const BlockDef& b : s.blocks) startEnergy_ += 0.5 * b.mass * lengthSquared(b.velocity);
    }
    void observe(Simulation& sim) override { overlap_ = std::max(overlap_, sim.penetration()); }
    double finish(Simulation& sim) override {
        double energy = 0.0;
        for (const Block& b : sim.blocks()) energy += 0.5 * b.mass * lengthSquared(b.velocity);
        return std::max(std::abs(energy - startEnergy_) / startEnergy_, overlap_ / size_);
    }

  private:
    double size_, startEnergy_ = 0.0, overlap_ = 0.0;
};

// A resting stack: the largest distance (m) any block moves from its start (sinking, jitter).
class StackDrift : public Measure {
  public:
    explicit StackDrift(const Scene& s) {
        for (const BlockDef& b : s.blocks) start_.push_back(b.position);
    }
    void observe(Simulation& sim) override {
        for (size_t i = 0; i < start_.size(); ++i)
            worst_ = std::max(worst_, length(sim.blocks()[i].position - start_[i]));
    }
    double finish(Simulation&) override { return worst_; }

  private:
    std::vector<Vec2> start_;
    double worst_ = 0.0;
};

// A block launched at v0 along the floor with friction mu slides to rest after
// d = v0^2 / (2·mu·g) (lecture, "Application: Platformer": friction; Coulomb friction decelerates
// it at mu·g): the distance (m) of its final x from x0 + d. The pair's mu mixes the block's face
// and the floor's (the world's) as the engine does (mixedFriction, world.h).
class StoppingDistance : public Measure {
  public:
    explicit StoppingDistance(const Scene& s) {
        const BlockDef& b = s.blocks.at(0);
        const double world = s.settings.friction;
        const double mu = mixedFriction(faceFriction(b.friction, world), world);
        const double g = -s.settings.gravity.y, v0 = std::abs(b.velocity.x);
        stopX_ = b.position.x + std::copysign(v0 * v0 / (2 * mu * g), b.velocity.x);
        duration = 1.5 * v0 / (mu * g); // at rest for the last third
    }
    double finish(Simulation& sim) override {
        return std::abs(sim.blocks().at(0).position.x - stopX_);
    }
    double duration = 0.0;

  private:
    double stopX_ = 0.0;
};

// Two blocks on a line, exact: they meet when the gap closes, then move on with the lecture's
// velocities v' = u - C(v - u).
std::vector<Vec2> twoBlocksExact(const Scene& s, double t) {
    const BlockDef &a = s.blocks.at(0), &b = s.blocks.at(1);
    const double gap = (b.position.x - a.position.x) - (a.size.x + b.size.x) / 2;
    const double meet = gap / (a.velocity.x - b.velocity.x);
    const double C = s.settings.bounciness;
    const double u = (a.mass * a.velocity.x + b.mass * b.velocity.x) / (a.mass + b.mass);
    const double va = u - C * (a.velocity.x - u), vb = u - C * (b.velocity.x - u);
    return {{a.position.x + a.velocity.x * meet + va * (t - meet), a.position.y},
            {b.position.x + b.velocity.x * meet + vb * (t - meet), b.position.y}};
}

// Newton's cradle with equal masses and C = 1: the striker stops against the row, the last block
// leaves with the striker's velocity, the ones between stay.
std::vector<Vec2> cradleExact(const Scene& s, double t) {
    std::vector<Vec2> exact;
    for (const BlockDef& b : s.blocks) exact.push_back(b.position);
    const BlockDef &striker = s.blocks.front(), &first = s.blocks[1];
    const double v = striker.velocity.x;
    const double meet =
        ((first.position.x - first.size.x / 2) - (striker.position.x + striker.size.x / 2)) / v;
    exact.front().x = first.position.x - (first.size.x + striker.size.x) / 2;
    exact.back().x += v * (t - meet);
    return exact;
}

struct Experiment {
    const char* scene;
    const char* unit;
    bool integrators; // gravity: the methods run with the exact integrator too
};
const Experiment kExperiments[] = {
    {"single_bounce", "relative energy error after 3 bounces", true},
    {"lecture_example_1", "m, position error", false},
    {"newtons_cradle", "m, position error", false},
    {"gas_100", "max(relative energy drift, overlap / size)", false},
    {"resting_stack", "m, largest displacement", true},
    {"friction_slide", "m, stopping-distance error", true},
};

struct Setup {
    std::unique_ptr<Measure> measure;
    double duration;
};

Setup setupFor(const std::string& name, const Scene& s) {
    if (name == "single_bounce") {
        auto m = std::make_unique<BounceEnergy>(s);
        const double d = m->duration;
        return {std::move(m), d};
    }
    if (name == "lecture_example_1")
        return {std::make_unique<FinalPositions>(twoBlocksExact(s, 1.5)), 1.5};
    if (name == "newtons_cradle")
        return {std::make_unique<FinalPositions>(cradleExact(s, 2.0)), 2.0};
    if (name == "gas_100") return {std::make_unique<GasDrift>(s), 5.0};
    if (name == "friction_slide") {
        auto m = std::make_unique<StoppingDistance>(s);
        const double d = m->duration;
        return {std::move(m), d};
    }
    return {std::make_unique<StackDrift>(s), 5.0};
}

// Runs one simulation for the experiment's duration (rounded to whole frames: the measures'
// exact answers are taken at the simulated time actually reached).
TradeoffRow runOne(const std::string& engine, const std::string& sceneName, const Scene& scene,
                   double dt, int substeps, const char* unit, Integrator integrator) {
    std::unique_ptr<Simulation> sim;
    Method method;
    const bool peer = !parseMethod(engine.c_str(), method);
    if (!peer) {
        Scene s = scene;
        s.settings.integrator = integrator;
        sim = makeEngineSimulation(s, method, dt, substeps);
    } else
        sim = makePeerSimulation(engine, scene, dt, substeps);
    Setup setup = setupFor(sceneName, scene);
    // Frames to reach the duration; the exact answers are at the duration itself, so the dt grid
    // divides the experiment durations only up to a fraction of a frame (part of the error).
    const long frames = std::max(1L, std::lround(setup.duration / dt));
    double ms = 0.0;
    for (long f = 0; f < frames; ++f) {
        ms += sim->step();
        setup.measure->observe(*sim);
    }
    TradeoffRow row;
    row.engine = engine;
    if (integrator != Integrator::SemiImplicitEuler) {
        row.integrator = integratorName(integrator);
        row.engine += ", " + row.integrator;
    }
    row.scene = sceneName;
    row.dt = dt;
    row.substeps = substeps;
    row.msPerSimulatedSecond = ms / (frames * dt);
    row.error = setup.measure->finish(*sim);
    row.errorUnit = unit;
    if (peer) row.lacks = settingsPeersLack(scene.settings);
    return row;
}

} // namespace

std::vector<TradeoffRow> runTradeoff(const TradeoffOptions& options) {
    std::vector<std::string> engines;
    for (int m = 0; m < static_cast<int>(Method::Count); ++m)
        engines.push_back(methodName(static_cast<Method>(m)));
    if (options.peers)
        for (const std::string& p : peerNames()) engines.push_back(p);

    std::vector<double> rates = {30, 60, 120, 240, 480, 960, 1920, 3840, 7680};
    if (options.quick) rates = {30, 120, 480};
    std::vector<TradeoffRow> rows;
    for (const Experiment& e : kExperiments) {
        if (!options.scenes.empty() && std::find(options.scenes.begin(), options.scenes.end(),
                                                 e.scene) == options.scenes.end())
            continue;
        const std::string path = options.scenesDir + "/" + e.scene + ".json";
        SceneResult loaded = loadSceneFile(path);
        if (!loaded.scene) throw std::runtime_error(loaded.error.text());
        for (const std::string& engine : engines) {
            for (double rate : rates) {
                for (int substeps : {1, 4}) {
                    if (substeps > 1 && rate * substeps > rates.back()) continue;
                    rows.push_back(runOne(engine, e.scene, *loaded.scene, 1.0 / rate, substeps,
                                          e.unit, Integrator::SemiImplicitEuler));
                    Method method;
                    if (e.integrators && substeps == 1 && parseMethod(engine.c_str(), method))
                        rows.push_back(runOne(engine, e.scene, *loaded.scene, 1.0 / rate, 1, e.unit,
                                              Integrator::Exact));
                }
            }
        }
    }
    return rows;
}

void writeTradeoffCsv(std::ostream& out, const std::vector<TradeoffRow>& rows) {
    out << "method,scene,dt,substeps,cost_ms_per_simulated_second,error,error_unit,integrator\n";
    out << std::setprecision(9);
    for (const TradeoffRow& r : rows)
        out << '"' << r.engine << "\"," << r.scene << ',' << r.dt << ',' << r.substeps << ','
            << r.msPerSimulatedSecond << ',' << r.error << ",\"" << r.errorUnit << "\","
            << r.integrator << "\n";
}

void writeTradeoffMarkdown(std::ostream& out, const std::vector<TradeoffRow>& rows) {
    out << "# Speed versus accuracy\n\n"
           "Cost is milliseconds of stepping per simulated second; error is per scene (below).\n"
           "Each cell: error at the given frame rate (1/dt), substeps 1.\n";
    std::map<std::string, std::vector<const TradeoffRow*>> byScene;
    std::vector<std::string> order;
    for (const TradeoffRow& r : rows) {
        if (!byScene.count(r.scene)) order.push_back(r.scene);
        byScene[r.scene].push_back(&r);
    }
    for (const std::string& scene : order) {
        const auto& list = byScene[scene];
        std::vector<double> rates;
        std::vector<std::string> engines;
        for (const TradeoffRow* r : list) {
            if (r->substeps != 1) continue;
            const double rate = std::round(1.0 / r->dt);
            if (std::find(rates.begin(), rates.end(), rate) == rates.end()) rates.push_back(rate);
            if (std::find(engines.begin(), engines.end(), r->engine) == engines.end())
                engines.push_back(r->engine);
        }
        out << "\n## " << scene << " (" << list.front()->errorUnit << ")\n\n| method |";
        for (double rate : rates) out << " " << static_cast<long>(rate) << " Hz |";
        out << "\n|---|";
        for (size_t i = 0; i < rates.size(); ++i) out << "---|";
        out << "\n";
        for (const std::string& engine : engines) {
            out << "| " << engine << " |";
            for (double rate : rates) {
                for (const TradeoffRow* r : list)
                    if (r->engine == engine && r->substeps == 1 && std::round(1.0 / r->dt) == rate)
                        out << " " << std::setprecision(2) << r->error << " ("
                            << r->msPerSimulatedSecond << " ms/s) |";
            }
            out << "\n";
        }
        for (const TradeoffRow* r : list)
            if (!r->lacks.empty()) {
                out << "\nThe peers ran without";
                for (const std::string& l : r->lacks) out << " " << l;
                out << " (they have nothing for it).\n";
                break;
            }
    }
}

bool writeTradeoffChart(const std::string& path, const std::vector<TradeoffRow>& rows,
                        std::string* error) {
    std::vector<ChartPanel> panels;
    for (const Experiment& e : kExperiments) {
        ChartPanel panel;
        panel.title = e.scene;
        panel.xLabel = "ms per simulated second";
        panel.yLabel = e.unit;
        std::map<std::string, ChartSeries> series;
        for (const TradeoffRow& r : rows) {
            if (r.scene != e.scene) continue;
            ChartSeries& s = series[r.engine];
            s.name = r.engine;
            s.points.push_back({r.msPerSimulatedSecond, r.error});
        }
        for (auto& [name, s] : series) {
            std::sort(s.points.begin(), s.points.end(),
                      [](const Vec2& a, const Vec2& b) { return a.x < b.x; });
            panel.series.push_back(std::move(s));
        }
        if (!panel.series.empty()) panels.push_back(std::move(panel));
    }
    return writeLogLogChart(path, panels, "Error against cost (log-log)", error);
}
