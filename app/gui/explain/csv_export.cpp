#include "csv_export.h"

#include <algorithm>

CsvTable timeSeriesTable(const TimeSeries& series, const std::vector<std::string>& channels) {
    CsvTable table;
    table.columns.push_back("t (s)");
    const int n = std::min(series.channels(), static_cast<int>(channels.size()));
    for (int c = 0; c < n; ++c) table.columns.push_back(channels[static_cast<std::size_t>(c)]);
    table.rows.reserve(series.size());
    for (std::size_t i = 0; i < series.size(); ++i) {
        std::vector<double> row{series.time(i)};
        for (int c = 0; c < n; ++c) row.push_back(series.value(i, c));
        table.rows.push_back(std::move(row));
    }
    return table;
}

CsvTable velocitySpaceTable(const VelocitySpacePath& path, const std::string& name1,
                            const std::string& name2) {
    CsvTable table;
    table.columns = {"t (s)", name1 + " vx (m/s)", name2 + " vx (m/s)",
                     "sqrt(m1)*v1 (sqrt(kg)*m/s)", "sqrt(m2)*v2 (sqrt(kg)*m/s)"};
    const VelocitySpacePair& pair = path.pair();
    for (const VelocitySpaceSample& s : path.samples()) {
        const Vec2 p = velocitySpacePoint(pair, s.v1, s.v2);
        table.rows.push_back({s.t, s.v1, s.v2, p.x, p.y});
    }
    return table;
}
