#include "student_trace.h"

#include "report.h"
#include "text_format.h"

#include <algorithm>
#include <cctype>

std::int64_t StudentTrace::firstDifference() const {
    if (!comparison || comparison->same()) return -1;
    return comparison->match.first().frame;
}

const TraceRow* StudentTrace::rowAt(std::int64_t frame) const {
    if (!trace) return nullptr;
    const auto it =
        std::lower_bound(trace->rows.begin(), trace->rows.end(), frame,
                         [](const TraceRow& row, std::int64_t f) { return row.frame < f; });
    return it != trace->rows.end() && it->frame == frame ? &*it : nullptr;
}

bool StudentTrace::ghostAt(std::int64_t frame, World& world) const {
    const TraceRow* row = rowAt(frame);
    if (!row) return false;
    for (std::size_t b = 0; b < trace->blocks.size(); ++b) {
        const auto index = static_cast<std::size_t>(trace->blocks[b]);
        if (index >= world.blocks.size()) return false;
        world.blocks[index].position = row->position[b];
        world.blocks[index].velocity = row->velocity[b];
    }
    return true;
}

std::optional<std::string> startStudentTrace(std::unique_ptr<TraceOpening>& opening,
                                             const std::string& path, const Scene& scene,
                                             const WorldSettings& settings,
                                             const TraceUnitsSpec& units) {
    WorldSettings reference = settings;
    reference.mistakes = 0;
    TraceResult read = loadTraceFile(path, scene, reference.dt, units);
    if (!read.trace) return read.error.text();
    opening = std::make_unique<TraceOpening>();
    opening->path = path;
    opening->units = units;
    opening->scene = scene;
    opening->scene.settings = reference;
    opening->trace = std::move(*read.trace);
    opening->comparer.emplace(opening->scene, reference, opening->trace,
                              traceTolerance(scene, reference.dt));
    return std::nullopt;
}

bool continueStudentTrace(TraceOpening& opening, StudentTrace& st) {
    if (!opening.comparer->done()) opening.comparer->step();
    if (!opening.comparer->done()) return false;
    st.path = opening.path;
    st.units = opening.units;
    st.scene = opening.scene;
    st.comparison = opening.comparer->take();
    st.trace = std::move(opening.trace);
    return true;
}

std::optional<std::string> openStudentTrace(StudentTrace& st, const std::string& path,
                                            const Scene& scene, const WorldSettings& settings,
                                            const TraceUnitsSpec& units) {
    std::unique_ptr<TraceOpening> opening;
    if (auto error = startStudentTrace(opening, path, scene, settings, units)) return error;
    while (!continueStudentTrace(*opening, st)) {
    }
    return std::nullopt;
}

std::string studentTraceSummary(const StudentTrace& st) {
    if (!st.open()) return "";
    const TraceComparison& c = *st.comparison;
    if (c.same()) return "the same as the reference over " + std::to_string(c.frames) + " frames";
    const Difference& d = c.match.first();
    return "different from frame " + std::to_string(d.frame) +
           " (t = " + formatQuantity(static_cast<double>(d.frame) * c.reference.dt, "s") +
           "): " + differenceName(st.scene, d) + " off by " +
           formatQuantity(d.by(), d.velocity ? "m/s" : "m");
}

bool isTraceFile(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".csv";
}
