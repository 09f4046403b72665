#include "csv.h"

#include <cmath>
#include <cstdio>
#include <sstream>

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

void writeCsv(std::ostream& out, const CsvTable& table) {
    for (std::size_t i = 0; i < table.columns.size(); ++i)
        out << (i ? "," : "") << csvField(table.columns[i]);
    out << '\n';
    char number[32];
    for (const std::vector<double>& row : table.rows) {
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (i) out << ',';
            if (std::isnan(row[i])) continue;
            std::snprintf(number, sizeof number, "%.17g", row[i]);
            out << number;
        }
        out << '\n';
    }
}

std::string csvText(const CsvTable& table) {
    std::ostringstream out;
    writeCsv(out, table);
    return out.str();
}
