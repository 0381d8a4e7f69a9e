#pragma once
// Measured road profiles in CSV: one line along the road, or several parallel lines.
//
// Format (all of it checked; anything else is an InputError naming the file, and the line):
//
//   # any comment lines
//   # y [mm] = -50, 0, 50          <- only with several lines: their lateral positions
//   x [mm], z_1 [mm], z_2 [mm], z_3 [mm]
//   0, 0.12, -0.05, 0.31
//   0.5, 0.10, , 0.33              <- an empty cell is a dropout
//   ...
//
// Columns (the header line, the first line that is not a comment):
//  - `x`: the position along the road, strictly increasing, every cell a finite number.
//  - either one height column `z`, or the numbered height columns `z_1`, `z_2`, ..., `z_n`
//    (each number once, all of 1..n, in any order). `z_k` lies at the k-th value of the y line.
//  - other columns (a time, an intensity) are ignored.
// Units: metres unless the column name carries one, as a suffix `x_mm`, `z_2_mm` or in
// brackets `x [mm]`, `z_2 [mm]`. Allowed units: m, mm, um (micrometres). Each column has its
// own unit; values are converted to metres.
// The y line: a comment `# y = v1, v2, ...` (m) or `# y [mm] = ...` / `# y_mm = ...`, with one
// finite value per height column, strictly increasing. It is required with more than one
// height column; with one it is optional (y = 0 otherwise). Only one y line per file.
// Cells: a finite decimal number, or (in a height column only) an empty cell: a dropout, a
// point where the instrument gave no reading. Text such as "nan" or "inf" is an error: write
// an empty cell for a missing value. A height line with no valid value at all is an error.
// Every data row has as many cells as the header has columns.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rollnoise {

struct ProfileTable {
  std::vector<double> x;                    // m, strictly increasing, finite
  std::vector<double> y;                    // m, one per line, strictly increasing
  std::vector<std::vector<double>> z_lines; // m, z_lines[line][row]; NaN marks a dropout
  std::string source;                       // the file (or text source) it came from
  std::size_t dropouts = 0;                 // empty height cells over all lines
};

// Parses profile CSV text; `source` names it in messages.
ProfileTable parse_profile_csv(const std::string& text, const std::string& source);
// Reads a profile CSV file; messages name the file.
ProfileTable read_profile_csv(const std::filesystem::path& path);

// The scale to metres of a unit name ("m", "mm", "um"); 0 when the unit is unknown.
double unit_to_metres(const std::string& unit);

}  // namespace rollnoise
