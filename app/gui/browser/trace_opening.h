// A file opened in the browser a step a frame (issue 41: the page never hangs). A scene opens in
// one step; a trace is read in one, then compared with the reference one simulated run a frame
// (student_trace.h), the page saying how far, so that a key waits for one run at most, not for
// the whole comparison (about 20 runs; the first trace of a page ran 3 to 4 s in one task: the
// browser's JIT had not yet optimised the variants' code). Pure logic: the web main calls it.
#pragma once

#include <memory>
#include <string>

struct App;
struct TraceOpening;

// The next step of opening `path` (`opening`: the trace being compared, kept between calls).
// True when it is over: opened, or refused with the error in the panel; false while a trace is
// still compared, with `progress` saying how far ("Comparing t.csv with the reference: run 3 of
// 13...").
bool openFileStep(App& app, std::unique_ptr<TraceOpening>& opening, const std::string& path,
                  std::string& progress);
