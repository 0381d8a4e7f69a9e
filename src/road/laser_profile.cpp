#include "road/laser_profile.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "road/profile_cleaning.hpp"

namespace rollnoise {
namespace {

constexpr std::string_view data_marker = "*****DATA*****";
constexpr std::string_view distance_name = "Distance (mm)";
constexpr std::string_view depth_name = "Depth (mm)";
constexpr std::size_t detection_window = 64 * 1024;

// Cuts `text` into lines ('\n', a trailing '\r' removed); `pos` advances.
std::string_view next_line(std::string_view text, std::size_t& pos) {
  const auto end = text.find('\n', pos);
  std::string_view line = text.substr(pos, (end == std::string_view::npos ? text.size() : end) - pos);
  pos = end == std::string_view::npos ? text.size() : end + 1;
  return line;
}

// The tab-separated field `index` of `line` (trimmed), or nullopt if there are fewer fields.
std::optional<std::string_view> field(std::string_view line, std::size_t index) {
  std::size_t start = 0;
  for (std::size_t i = 0; i < index; ++i) {
    const auto tab = line.find('\t', start);
    if (tab == std::string_view::npos) return std::nullopt;
    start = tab + 1;
  }
  const auto tab = line.find('\t', start);
  return trim_blanks(line.substr(start, tab == std::string_view::npos ? std::string_view::npos : tab - start));
}

bool is_marker(std::string_view line) {
  const auto first = field(line, 0);
  return first && *first == data_marker;
}

// Column index of `name` in the column header, if present.
std::optional<std::size_t> column(std::string_view header, std::string_view name) {
  for (std::size_t c = 0; c < 64; ++c) {
    const auto f = field(header, c);
    if (!f) return std::nullopt;
    if (*f == name) return c;
  }
  return std::nullopt;
}

// Index range [begin, end) of the road between the reference plates of `z` (heights, NaN for
// dropouts), by the rules of laser_profile.hpp.
std::pair<std::size_t, std::size_t> road_between_plates(const std::vector<double>& z, double spacing_m) {
  const std::size_t n = z.size();
  // The road's level: the median of the middle third (plates lie at the ends), or of the whole
  // record if the middle third saw nothing.
  std::vector<double> valid;
  valid.reserve(n);
  for (std::size_t i = n / 3; i < n - n / 3; ++i)
    if (!std::isnan(z[i])) valid.push_back(z[i]);
  if (valid.empty()) {
    for (double v : z)
      if (!std::isnan(v)) valid.push_back(v);
  }
  if (valid.empty()) return {0, n};  // all dropouts: clean_profile reports it
  const auto middle = valid.begin() + static_cast<std::ptrdiff_t>(valid.size() / 2);
  std::nth_element(valid.begin(), middle, valid.end());
  const double road_level = *middle;

  const auto min_run = std::max<std::size_t>(3, static_cast<std::size_t>(std::ceil(laser_plate_min_run_m / spacing_m)));
  const auto buffer = static_cast<std::size_t>(std::ceil(laser_plate_buffer_m / spacing_m));
  std::size_t begin = 0;
  std::size_t end = n;
  bool have_end = false;
  bool plate = false;  // state of the last valid sample (dropouts inherit it)
  std::size_t run_start = 0;
  for (std::size_t i = 0; i <= n; ++i) {
    const bool now = i < n && (std::isnan(z[i]) ? plate : z[i] - road_level > laser_plate_min_height_m);
    if (now && !plate) run_start = i;
    if (!now && plate && i - run_start >= min_run) {  // a plate run [run_start, i) ends
      if (run_start < n / 2) {
        begin = i;  // the last run starting in the first half bounds the road from the left
      } else if (!have_end) {
        end = run_start;  // the first run starting in the second half bounds it on the right
        have_end = true;
      }
    }
    plate = now;
  }
  if (begin > 0) begin += buffer;
  if (have_end) end = end > buffer ? end - buffer : 0;
  return {begin, std::max(begin, end)};
}

}  // namespace

bool looks_like_laser_profile(std::string_view text) {
  text = text.substr(0, detection_window);
  std::size_t pos = 0;
  while (pos < text.size()) {
    if (is_marker(next_line(text, pos))) {
      std::string_view header;
      while (pos < text.size() && trim_blanks(header).empty()) header = next_line(text, pos);
      return column(header, distance_name).has_value() && column(header, depth_name).has_value();
    }
  }
  return false;
}

MeasuredProfile parse_laser_profile(std::string_view text, const std::string& source) {
  if (text.size() > laser_max_bytes) {
    throw InputError(source, "", "larger than " + std::to_string(laser_max_bytes >> 20) +
                                     " MiB: not a laser profile this reader accepts");
  }
  std::size_t pos = 0;
  std::size_t line_number = 0;
  bool marker = false;
  while (pos < text.size() && !marker) {
    marker = is_marker(next_line(text, pos));
    ++line_number;
  }
  if (!marker) {
    throw InputError(source, "", "no line \"*****DATA*****\": not a stationary laser profile file");
  }
  std::string_view header;
  while (pos < text.size() && trim_blanks(header).empty()) {
    header = next_line(text, pos);
    ++line_number;
  }
  const std::string header_where = "line " + std::to_string(line_number);
  const auto c_distance = column(header, distance_name);
  const auto c_depth = column(header, depth_name);
  if (!c_distance || !c_depth) {
    throw InputError(source, header_where,
                     "the column header after \"*****DATA*****\" must name \"Distance (mm)\" and "
                     "\"Depth (mm)\" (is \"" + printable_excerpt(header) + "\")");
  }

  std::vector<double> x_mm;
  std::vector<double> z;
  while (pos < text.size()) {
    const std::string_view line = next_line(text, pos);
    ++line_number;
    if (trim_blanks(line).empty()) continue;
    const auto where = [&] { return "line " + std::to_string(line_number); };
    const auto distance_field = field(line, *c_distance);
    const auto depth_field = field(line, *c_depth);
    if (!distance_field || !depth_field) {
      throw InputError(source, where(), "too few tab-separated fields (needs \"Distance (mm)\" and \"Depth (mm)\")");
    }
    const auto distance = parse_finite_number(*distance_field);
    if (!distance) {
      throw InputError(source, where() + ", Distance (mm)",
                       "\"" + printable_excerpt(*distance_field) + "\" is not a finite number");
    }
    if (!x_mm.empty() && !(*distance > x_mm.back())) {
      throw InputError(source, where() + ", Distance (mm)",
                       format_number(*distance) + " is not greater than the row before (" +
                           format_number(x_mm.back()) + "): distances must increase");
    }
    double height = std::nan("");
    if (!is_dropout_cell(*depth_field)) {
      const auto depth = parse_finite_number(*depth_field);
      if (!depth) {
        throw InputError(source, where() + ", Depth (mm)",
                         "\"" + printable_excerpt(*depth_field) + "\" is neither a finite number nor NaN");
      }
      height = *depth * 1e-3;  // "depth" grows upwards: see the header
    }
    x_mm.push_back(*distance);
    z.push_back(height);
  }
  if (x_mm.size() < 2) {
    throw InputError(source, "", "needs at least 2 data rows (has " + std::to_string(x_mm.size()) + ")");
  }

  // Uniform sampling: distances are written rounded (to 1 µm), so steps may differ by that.
  const double spacing_mm = (x_mm.back() - x_mm.front()) / static_cast<double>(x_mm.size() - 1);
  for (std::size_t i = 1; i < x_mm.size(); ++i) {
    const double step = x_mm[i] - x_mm[i - 1];
    if (step < 0.5 * spacing_mm || step > 1.5 * spacing_mm) {
      throw InputError(source, "data row " + std::to_string(i + 1),
                       "the step from the row before is " + format_number(step) +
                           " mm, the mean step is " + format_number(spacing_mm) +
                           " mm: the profile must be sampled uniformly");
    }
  }

  MeasuredProfile profile;
  profile.source = source;
  profile.spacing_m = spacing_mm * 1e-3;
  const auto [begin, end] = road_between_plates(z, profile.spacing_m);
  if (end - begin < 2) {
    throw InputError(source, "", "no road left between the reference plates (" +
                                     std::to_string(end - begin) + " rows)");
  }
  profile.trimmed_points = z.size() - (end - begin);
  profile.x0_m = x_mm[begin] * 1e-3;
  profile.z_m.assign(z.begin() + static_cast<std::ptrdiff_t>(begin), z.begin() + static_cast<std::ptrdiff_t>(end));
  try {
    const CleaningReport report = clean_profile(profile.z_m, profile.spacing_m);
    profile.dropouts = report.dropouts;
    profile.spikes = report.spikes;
  } catch (const InputError& e) {
    throw e.with_source(source);
  }
  return profile;
}

MeasuredProfile read_laser_profile(const std::filesystem::path& path) {
  return parse_laser_profile(read_text_file(path, laser_max_bytes, "laser profile"), path.string());
}

}  // namespace rollnoise
