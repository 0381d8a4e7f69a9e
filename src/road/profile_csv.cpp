#include "road/profile_csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>
#include <utility>

#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

const char* const allowed_units = "m, mm or um";

// A column name split into its quantity and unit: "z_2 [mm]" -> ("z_2", "mm"), "x_mm" ->
// ("x", "mm"), "z" -> ("z", ""). `bracketed` tells whether the unit was written in brackets
// (then an unknown unit is an error, not part of the name).
struct ColumnName {
  std::string quantity;
  std::string unit;
  bool bracketed = false;
};

ColumnName split_unit(std::string_view name) {
  name = trim_blanks(name);
  ColumnName out;
  if (!name.empty() && name.back() == ']') {
    const auto open = name.rfind('[');
    if (open != std::string_view::npos) {
      out.quantity = std::string(trim_blanks(name.substr(0, open)));
      out.unit = std::string(trim_blanks(name.substr(open + 1, name.size() - open - 2)));
      out.bracketed = true;
      return out;
    }
  }
  for (const char* unit : {"mm", "um", "m"}) {
    const std::string suffix = std::string("_") + unit;
    if (name.size() > suffix.size() && name.substr(name.size() - suffix.size()) == suffix) {
      out.quantity = std::string(name.substr(0, name.size() - suffix.size()));
      out.unit = unit;
      return out;
    }
  }
  out.quantity = std::string(name);
  return out;
}

// The line number k of "z_k" (k >= 1, no leading zeros), or 0 when `quantity` is not of that form.
std::size_t height_index(const std::string& quantity) {
  if (quantity.size() < 3 || quantity.compare(0, 2, "z_") != 0) return 0;
  if (quantity[2] == '0') return 0;
  std::size_t k = 0;
  const char* first = quantity.data() + 2;
  const char* last = quantity.data() + quantity.size();
  const auto [ptr, ec] = std::from_chars(first, last, k);
  if (ec != std::errc() || ptr != last) return 0;
  return k;
}

double column_scale(const ColumnName& column, const std::string& header, const std::string& source) {
  if (column.unit.empty()) return 1.0;
  const double scale = unit_to_metres(column.unit);
  if (scale == 0.0) {
    throw InputError(source, "header, column \"" + header + "\"",
                     "unknown unit \"" + printable_excerpt(column.unit) + "\"; allowed units are " +
                         allowed_units + " (metres when no unit is given)");
  }
  return scale;
}

// The y line: a comment "y = ...", "y [mm] = ..." or "y_mm = ...". std::nullopt when `comment`
// is some other comment.
std::optional<std::vector<double>> parse_y_line(std::string_view comment, const std::string& source) {
  const std::string_view text = trim_blanks(comment);
  const auto eq = text.find('=');
  if (eq == std::string_view::npos) return std::nullopt;
  const ColumnName name = split_unit(text.substr(0, eq));
  if (name.quantity != "y") return std::nullopt;
  const std::string where = "the y line \"# " + printable_excerpt(text) + "\"";
  double scale = 1.0;
  if (!name.unit.empty()) {
    scale = unit_to_metres(name.unit);
    if (scale == 0.0) {
      throw InputError(source, where,
                       "unknown unit \"" + printable_excerpt(name.unit) + "\"; allowed units are " +
                           allowed_units + " (metres when no unit is given)");
    }
  }
  std::vector<double> values;
  std::string_view rest = text.substr(eq + 1);
  while (true) {
    const auto comma = rest.find(',');
    const std::string_view field = trim_blanks(rest.substr(0, comma));
    double value = 0.0;
    const char* first = field.data();
    const char* last = field.data() + field.size();
    if (first != last && *first == '+') ++first;
    const auto [ptr, ec] = std::from_chars(first, last, value);
    if (field.empty() || ec != std::errc() || ptr != last || !std::isfinite(value * scale)) {
      throw InputError(source, where,
                       "\"" + printable_excerpt(field) +
                           "\" is not a finite number; write the lateral position of each height "
                           "column, such as \"# y [mm] = -50, 0, 50\"");
    }
    values.push_back(value * scale);
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  for (std::size_t k = 1; k < values.size(); ++k) {
    if (!(values[k] > values[k - 1])) {
      throw InputError(source, where, "the y positions must be strictly increasing (z_1 the smallest y)");
    }
  }
  return values;
}

}  // namespace

double unit_to_metres(const std::string& unit) {
  if (unit == "m") return 1.0;
  if (unit == "mm") return 1e-3;
  if (unit == "um" || unit == "\xC2\xB5m" || unit == "\xCE\xBCm") return 1e-6;  // um, µm (micro sign, mu)
  return 0.0;
}

ProfileTable parse_profile_csv(const std::string& text, const std::string& source) {
  const NumericCsv csv = parse_numeric_csv(text, source, EmptyCells::as_nan);
  ProfileTable out;
  out.source = source;

  // The columns: x, and z or z_1 .. z_n.
  std::optional<std::size_t> x_column;
  double x_scale = 1.0;
  std::optional<std::size_t> single_z;
  std::vector<std::pair<std::size_t, std::size_t>> numbered;  // (k, column)
  std::vector<double> z_scales(csv.header.size(), 1.0);
  for (std::size_t c = 0; c < csv.header.size(); ++c) {
    const std::string& header = csv.header[c];
    const ColumnName name = split_unit(header);
    const std::string where = "header, column \"" + header + "\"";
    const std::size_t k = height_index(name.quantity);
    if (name.quantity == "x") {
      if (x_column) throw InputError(source, where, "a second x column; give x once");
      x_column = c;
      x_scale = column_scale(name, header, source);
    } else if (name.quantity == "z") {
      if (single_z) throw InputError(source, where, "a second z column; for several lines name them z_1, z_2, ...");
      single_z = c;
      z_scales[c] = column_scale(name, header, source);
    } else if (k > 0) {
      for (const auto& [other, column] : numbered) {
        if (other == k) throw InputError(source, where, "repeats the height column z_" + std::to_string(k));
      }
      numbered.emplace_back(k, c);
      z_scales[c] = column_scale(name, header, source);
    } else if (name.bracketed && (name.quantity == "x" || name.quantity.rfind("z", 0) == 0)) {
      throw InputError(source, where, "not a profile column name; use x, z or z_1, z_2, ...");
    }
  }
  const std::string expected =
      "a profile needs a column x and a height column z (one line) or z_1, z_2, ... (several "
      "lines), in m unless a unit is given (x_mm or \"x [mm]\"; units m, mm, um)";
  if (!x_column) throw InputError(source, "header", "no column \"x\"; " + expected);
  if (single_z && !numbered.empty()) {
    throw InputError(source, "header", "has both a z column and numbered z_k columns; " + expected);
  }
  if (!single_z && numbered.empty()) throw InputError(source, "header", "no height column \"z\" (or \"z_1\", \"z_2\", ...); " + expected);
  std::vector<std::size_t> z_columns;
  if (single_z) {
    z_columns.push_back(*single_z);
  } else {
    std::sort(numbered.begin(), numbered.end());
    for (std::size_t i = 0; i < numbered.size(); ++i) {
      if (numbered[i].first != i + 1) {
        throw InputError(source, "header",
                         "the height columns must be z_1 to z_" + std::to_string(numbered.size()) +
                             "; z_" + std::to_string(i + 1) + " is missing");
      }
      z_columns.push_back(numbered[i].second);
    }
  }

  // The y line.
  std::optional<std::vector<double>> y;
  for (const auto& comment : csv.comments) {
    if (auto values = parse_y_line(comment, source)) {
      if (y) throw InputError(source, "the y line", "is given twice; give the lateral positions once");
      y = std::move(values);
    }
  }
  if (y) {
    if (y->size() != z_columns.size()) {
      throw InputError(source, "the y line",
                       "gives " + std::to_string(y->size()) + " lateral positions for " +
                           std::to_string(z_columns.size()) + " height column(s); give one per column");
    }
    out.y = std::move(*y);
  } else if (z_columns.size() == 1) {
    out.y = {0.0};
  } else {
    throw InputError(source, "header",
                     "has " + std::to_string(z_columns.size()) +
                         " height columns but no y line; add a comment line with their lateral "
                         "positions, such as \"# y [mm] = -50, 0, 50\" or \"# y = -0.05, 0, 0.05\" (m)");
  }

  // The data.
  const std::size_t rows = csv.rows();
  if (rows < 2) {
    throw InputError(source, "", "needs at least 2 data rows (has " + std::to_string(rows) + ")");
  }
  const auto row_where = [&](std::size_t r) {
    return "line " + std::to_string(csv.row_lines[r]) + " (data row " + std::to_string(r + 1) + "), column \"" +
           csv.header[*x_column] + "\"";
  };
  out.x.resize(rows);
  for (std::size_t r = 0; r < rows; ++r) {
    const double x = csv.columns[*x_column][r] * x_scale;
    if (std::isnan(csv.columns[*x_column][r])) {
      throw InputError(source, row_where(r), "is empty; every row needs its position x (only heights may be missing)");
    }
    if (!std::isfinite(x)) throw InputError(source, row_where(r), "x must be a finite number");
    if (r > 0 && !(x > out.x[r - 1])) {
      throw InputError(source, row_where(r),
                       "x = " + format_number(x) + " m is not greater than x = " + format_number(out.x[r - 1]) +
                           " m of the row before; x must be strictly increasing");
    }
    out.x[r] = x;
  }
  for (std::size_t line = 0; line < z_columns.size(); ++line) {
    const std::size_t c = z_columns[line];
    std::vector<double> z(rows);
    std::size_t valid = 0;
    for (std::size_t r = 0; r < rows; ++r) {
      z[r] = csv.columns[c][r] * z_scales[c];  // NaN (a dropout) stays NaN
      if (std::isnan(z[r])) {
        ++out.dropouts;
      } else {
        ++valid;
      }
    }
    if (valid == 0) {
      throw InputError(source, "column \"" + csv.header[c] + "\"",
                       "has no value at all (every cell is a dropout); a height line needs measured values");
    }
    out.z_lines.push_back(std::move(z));
  }
  return out;
}

ProfileTable read_profile_csv(const std::filesystem::path& path) {
  return parse_profile_csv(read_text_file(path), path.string());
}

}  // namespace rollnoise
