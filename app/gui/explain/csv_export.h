// The plots' data out, for lab reports: each plot's series as a CSV table (a header row, one row
// per sample, t first), written next to where Ctrl+S saves, under a name from the scene and the
// plot that is never an existing file (lecture_example_1-momentum.csv, then -2, ...). The panel
// says where; the browser build downloads the file (exportCsv in app.h writes it). Pure logic.
#pragma once

#include "csv.h"
#include "plot_logic.h"
#include "velocity_space.h"

#include <string>
#include <vector>

// `series` as a table: "t" (s), then one column per channel, named `channels` (with units).
CsvTable timeSeriesTable(const TimeSeries& series, const std::vector<std::string>& channels);
// The velocity-space path: t (s), v1 and v2 (m/s), and the plotted coordinates sqrt(m1)·v1 and
// sqrt(m2)·v2 (sqrt(kg)·m/s), the blocks named as given.
CsvTable velocitySpaceTable(const VelocitySpacePath& path, const std::string& name1,
                            const std::string& name2);
