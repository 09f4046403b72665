// CSV for spreadsheets (lab reports): one quoting rule for text, and tables of numbers written
// so that they read back exactly. Used by sandbox-cli run --trace and the app's plot exports.
#pragma once

#include <ostream>
#include <string>
#include <vector>

// A CSV field: quoted, quotes doubled, control bytes (never echoed raw) as spaces.
std::string csvField(const std::string& text);

// A table of numbers under a header row.
struct CsvTable {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows; // each as long as `columns`
};

// The header (each name a csvField) and one line per row, numbers with 17 significant digits
// (they read back bit for bit); a NaN is an empty cell. Lines end with "\n".
void writeCsv(std::ostream& out, const CsvTable& table);
std::string csvText(const CsvTable& table);
