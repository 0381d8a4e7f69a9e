#include "calibrate/frf_csv_reader.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string_view>

#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

std::string line_name(std::size_t number) { return "line " + std::to_string(number); }

// The lines of the text as parse_numeric_csv sees them: the line numbers of the data rows (the
// header excluded) and the `key = value` comment lines.
struct CsvLayout {
  std::vector<std::size_t> data_lines;
  struct Setting {
    std::string value;
    std::size_t line = 0;
  };
  std::map<std::string, Setting, std::less<>> settings;
};

const std::vector<std::string>& setting_keys() {
  static const std::vector<std::string> keys = {"data_type", "response_x", "response_y", "excitation_x",
                                                "excitation_y"};
  return keys;
}

CsvLayout scan_layout(const std::string& text, const std::string& source) {
  CsvLayout layout;
  std::size_t pos = 0;
  std::size_t number = 0;
  bool header_seen = false;
  while (pos < text.size()) {
    const auto end = text.find('\n', pos);
    std::string_view line(text.data() + pos, (end == std::string::npos ? text.size() : end) - pos);
    pos = end == std::string::npos ? text.size() : end + 1;
    ++number;
    if (number == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
    const std::string_view content = trim_blanks(line);
    if (content.empty()) continue;
    if (content.front() != '#') {
      if (header_seen) layout.data_lines.push_back(number);
      header_seen = true;
      continue;
    }
    const std::string_view comment = trim_blanks(content.substr(1));
    const auto equals = comment.find('=');
    if (equals == std::string_view::npos) continue;
    const std::string_view key = trim_blanks(comment.substr(0, equals));
    bool known = false;
    for (const auto& k : setting_keys()) known = known || key == k;
    if (!known) continue;  // free text such as "# generated with mass = 1 kg"
    if (layout.settings.count(key) > 0)
      throw InputError(source, line_name(number),
                       "'" + std::string(key) + "' is given twice (first on line " +
                           std::to_string(layout.settings.find(key)->second.line) + ")");
    std::string_view value = trim_blanks(comment.substr(equals + 1));
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"') value = value.substr(1, value.size() - 2);
    layout.settings.emplace(std::string(key), CsvLayout::Setting{std::string(value), number});
  }
  return layout;
}

std::optional<double> position_setting(const CsvLayout& layout, const std::string& key, const std::string& source) {
  const auto it = layout.settings.find(key);
  if (it == layout.settings.end()) return std::nullopt;
  const std::string& text = it->second.value;
  double value = 0.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (text.empty() || ec != std::errc() || ptr != last || !std::isfinite(value))
    throw InputError(source, line_name(it->second.line) + ", " + key,
                     "\"" + printable_excerpt(text) + "\" is not a finite number (a position in m)");
  return value;
}

// response_x/response_y (or excitation_...) as a position; both or neither must be given.
std::optional<BeltPosition> position(const CsvLayout& layout, const std::string& which, const std::string& source) {
  const auto x = position_setting(layout, which + "_x", source);
  const auto y = position_setting(layout, which + "_y", source);
  if (x.has_value() != y.has_value()) {
    const std::string given = x ? which + "_x" : which + "_y";
    const std::string missing = x ? which + "_y" : which + "_x";
    throw InputError(source, line_name(layout.settings.find(given)->second.line),
                     "'" + given + "' is given without '" + missing + "': give both (m)");
  }
  if (!x) return std::nullopt;
  return BeltPosition{*x, *y};
}

FrfQuantity quantity(const CsvLayout& layout, const FrfReadOptions& options, const std::string& source) {
  const auto it = layout.settings.find("data_type");
  if (it == layout.settings.end()) return options.quantity;
  const auto parsed = parse_frf_quantity(it->second.value);
  const std::string where = line_name(it->second.line) + ", data_type";
  if (!parsed)
    throw InputError(source, where,
                     "\"" + printable_excerpt(it->second.value) + "\" is not a quantity calibrate fits; allowed: " +
                         frf_quantity_choices() + " (motion over force)");
  if (options.quantity_given && *parsed != options.quantity)
    throw InputError(source, where,
                     "the file holds " + frf_quantity_name(*parsed) + ", but --data-type says " +
                         frf_quantity_name(options.quantity));
  return *parsed;
}

}  // namespace

FrfFile parse_frf_csv(const std::string& text, const std::string& source, const FrfReadOptions& options) {
  const NumericCsv csv = parse_numeric_csv(text, source);
  const CsvLayout layout = scan_layout(text, source);

  const auto has = [&csv](const char* name) {
    for (const auto& h : csv.header)
      if (h == name) return true;
    return false;
  };
  std::string frequency_column;
  double to_hz = 1.0;
  if (has("frequency_hz")) {
    frequency_column = "frequency_hz";
  } else if (has("frequency_khz")) {
    frequency_column = "frequency_khz";
    to_hz = 1000.0;
  } else if (has("angular_frequency_rad_s")) {
    frequency_column = "angular_frequency_rad_s";
    to_hz = 1.0 / (2.0 * std::numbers::pi);
  }
  const bool cartesian = has("re") && has("im");
  const bool polar = has("magnitude") && has("phase_deg");
  if (frequency_column.empty() || csv.header.size() != 3 || cartesian == polar) {
    std::string have;
    for (const auto& h : csv.header) {
      if (!have.empty()) have += ",";
      have += h;
    }
    throw InputError(source, "header",
                     "columns \"" + have +
                         "\" are not an FRF; allowed: frequency_hz,re,im or frequency_hz,magnitude,phase_deg "
                         "(frequency_khz or angular_frequency_rad_s in place of frequency_hz)");
  }
  if (csv.rows() == 0) throw InputError(source, "", "holds no data rows after the header");

  FrfFile file;
  MeasuredFrf frf;
  frf.source = source;
  frf.quantity = quantity(layout, options, source);
  frf.response = position(layout, "response", source);
  frf.excitation = position(layout, "excitation", source);

  const auto& f = csv.columns[csv.column(frequency_column, source)];
  const auto& a = csv.columns[csv.column(cartesian ? "re" : "magnitude", source)];
  const auto& b = csv.columns[csv.column(cartesian ? "im" : "phase_deg", source)];
  const auto where = [&layout](std::size_t row) {
    return row < layout.data_lines.size() ? line_name(layout.data_lines[row]) : "row " + std::to_string(row + 1);
  };
  std::vector<double> hz(csv.rows());
  std::vector<std::complex<double>> values(csv.rows());
  for (std::size_t row = 0; row < csv.rows(); ++row) {
    hz[row] = f[row] * to_hz;
    if (cartesian) {
      values[row] = {a[row], b[row]};
    } else {
      if (a[row] < 0.0)
        throw InputError(source, where(row) + ", column \"magnitude\"",
                         "magnitude " + format_number(a[row]) + " is negative; a magnitude is >= 0");
      values[row] = std::polar(a[row], b[row] * std::numbers::pi / 180.0);
    }
  }
  fill_mobility(frf, hz, values, where, file.notes);
  file.frfs.push_back(std::move(frf));
  return file;
}

FrfFile read_frf_csv(const std::filesystem::path& path, const FrfReadOptions& options) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string(), "", "file not found (or not a regular file)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot be opened for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse_frf_csv(buffer.str(), path.string(), options);
}

}  // namespace rollnoise
