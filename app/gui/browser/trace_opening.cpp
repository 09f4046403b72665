#include "trace_opening.h"

#include "app.h"
#include "printable.h"
#include "student_trace.h"

#include <filesystem>

namespace {

std::string comparingMessage(const TraceOpening& opening) {
    return "Comparing " + printable(std::filesystem::path(opening.path).filename().string()) +
           " with the reference: run " + std::to_string(opening.comparer->runsDone() + 1) + " of " +
           std::to_string(opening.comparer->runsPlanned()) + "...";
}

} // namespace

bool openFileStep(App& app, std::unique_ptr<TraceOpening>& opening, const std::string& path,
                  std::string& progress) {
    if (!isTraceFile(path)) {
        openFile(app, path);
        return true;
    }
    // A scene opened or an edit made since the trace was read: compare again on the world as it
    // is now, as the window's openTrace compares with the current scene and settings.
    if (opening && app.sim.changes != opening->changesAtStart) opening.reset();
    if (!opening) {
        if (const auto error = startStudentTrace(
                opening, path, app.sim.scene, app.sim.world().settings, app.studentTrace.units)) {
            app.ui.messages.error = *error;
            return true;
        }
        opening->changesAtStart = app.sim.changes;
    } else if (continueStudentTrace(*opening, app.studentTrace)) {
        opening.reset();
        showOpenedTrace(app);
        return true;
    }
    progress = comparingMessage(*opening);
    return false;
}
