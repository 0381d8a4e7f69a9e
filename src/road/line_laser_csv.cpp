#include "road/line_laser_csv.hpp"

#include <cmath>
#include <optional>
#include <string>

#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

constexpr std::string_view utf8_bom = "\xEF\xBB\xBF";

// Cuts `text` into lines ('\n', a trailing '\r' removed); `pos` advances.
std::string_view next_line(std::string_view text, std::size_t& pos) {
  const auto end = text.find('\n', pos);
  std::string_view line = text.substr(pos, (end == std::string_view::npos ? text.size() : end) - pos);
  pos = end == std::string_view::npos ? text.size() : end + 1;
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

// The comma-separated fields of `line`, trimmed; calls `each(index, field)` until it returns
// false. Returns the number of fields visited.
template <class Each>
std::size_t for_each_field(std::string_view line, Each each) {
  std::size_t index = 0;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    const std::string_view field =
        trim_blanks(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (!each(index, field)) return index + 1;
    ++index;
    if (comma == std::string_view::npos) return index;
    start = comma + 1;
  }
}

std::string_view first_field(std::string_view line) { return trim_blanks(line.substr(0, line.find(','))); }

std::string_view without_bom(std::string_view text) {
  if (text.substr(0, utf8_bom.size()) == utf8_bom) text.remove_prefix(utf8_bom.size());
  return text;
}

}  // namespace

bool looks_like_line_laser_csv(std::string_view head) {
  head = without_bom(head);
  std::size_t pos = 0;
  std::string_view first;
  while (pos < head.size() && trim_blanks(first).empty()) first = next_line(head, pos);
  // The first line must be whole within the head (a line cut off may end in half a number).
  if (trim_blanks(first).empty() || head.find('\n') == std::string_view::npos) return false;
  bool numbers = true;
  const std::size_t fields = for_each_field(first, [&](std::size_t, std::string_view f) {
    numbers = parse_finite_number(f).has_value();
    return numbers;
  });
  if (!numbers || fields < 3) return false;
  std::string_view second;
  while (pos < head.size() && trim_blanks(second).empty()) second = next_line(head, pos);
  return second.find(',') != std::string_view::npos && first_field(second) == first_field(first);
}

LineLaserProfiles parse_line_laser_csv(std::string_view text, const std::string& source) {
  if (text.size() > line_laser_max_bytes) {
    throw InputError(source, "", "larger than " + std::to_string(line_laser_max_bytes >> 20) +
                                     " MiB: not a line laser file this reader accepts");
  }
  text = without_bom(text);
  LineLaserProfiles out;
  out.source = source;
  std::size_t pos = 0;
  std::size_t line_number = 0;
  // The next line that is not blank, and its number (1-based); empty at the end.
  const auto next_data_line = [&](std::size_t& number) {
    while (pos < text.size()) {
      const std::string_view line = next_line(text, pos);
      ++line_number;
      if (!trim_blanks(line).empty()) {
        number = line_number;
        return line;
      }
    }
    number = 0;
    return std::string_view();
  };
  const auto line_key = [](std::size_t number) { return "line " + std::to_string(number); };

  // Reads the values after the time stamp of `line` into `values` (positions: every cell a
  // number; heights: NaN for a dropout), at most `limit` of them and one more (enough to tell
  // that there are too many: an empty cell costs one byte of text, its value eight); returns the
  // time stamp.
  const auto read_line = [&](std::string_view line, std::size_t number, bool heights, std::size_t limit,
                             std::vector<double>& values) {
    values.clear();
    double stamp = 0.0;
    for_each_field(line, [&](std::size_t index, std::string_view f) {
      if (index == 0) {
        const auto t = parse_finite_number(f);
        if (!t) {
          throw InputError(source, line_key(number) + ", field 1 (time stamp)",
                           "\"" + printable_excerpt(f) + "\" is not a finite number: each line begins with the "
                           "profile's time stamp, such as 145327.039720");
        }
        stamp = *t;
        return true;
      }
      if (values.size() > limit) return false;
      const std::string key = line_key(number) + ", field " + std::to_string(index + 1);
      if (heights && is_dropout_cell(f)) {
        values.push_back(std::nan(""));
        return true;
      }
      const auto v = parse_finite_number(f);
      if (!v) {
        throw InputError(source, key,
                         "\"" + printable_excerpt(f) + "\" is not a finite number" +
                             (heights ? std::string(" (a height in mm; an empty cell or NaN marks a dropout)")
                                      : std::string(" (a position in mm)")));
      }
      values.push_back(*v * 1e-3);  // mm -> m
      return true;
    });
    return stamp;
  };

  std::vector<double> positions;
  std::vector<double> heights;
  while (true) {
    std::size_t position_line = 0;
    const std::string_view first = next_data_line(position_line);
    if (position_line == 0) break;
    std::size_t height_line = 0;
    const std::string_view second = next_data_line(height_line);
    if (height_line == 0) {
      throw InputError(source, line_key(position_line),
                       "is a line of positions without its line of heights: the file holds pairs of lines "
                       "(time stamp and positions in mm, then the same time stamp and the heights in mm)");
    }
    const double stamp = read_line(first, position_line, false, text.size(), positions);
    const double stamp2 = read_line(second, height_line, true, positions.size(), heights);
    if (stamp != stamp2) {
      throw InputError(source, line_key(height_line) + ", field 1 (time stamp)",
                       format_number(stamp2) + " differs from the time stamp " + format_number(stamp) + " of line " +
                           std::to_string(position_line) +
                           ": each line of positions must be followed by the heights of the same profile");
    }
    if (positions.size() < 2) {
      throw InputError(source, line_key(position_line),
                       "has " + std::to_string(positions.size()) + " positions after the time stamp; a profile needs at least 2");
    }
    if (heights.size() != positions.size()) {
      throw InputError(source, line_key(height_line),
                       "has " + (heights.size() > positions.size() ? std::string("more") : std::to_string(heights.size())) +
                           " heights but line " + std::to_string(position_line) +
                           " has " + std::to_string(positions.size()) + " positions: give one height per position");
    }
    for (std::size_t i = 1; i < positions.size(); ++i) {
      if (!(positions[i] > positions[i - 1])) {
        throw InputError(source, line_key(position_line) + ", field " + std::to_string(i + 2),
                         format_number(positions[i] * 1e3) + " mm is not greater than the position before (" +
                             format_number(positions[i - 1] * 1e3) + " mm): positions must increase");
      }
    }
    if (out.z_lines.empty()) {
      out.x_m = positions;
    } else {
      if (positions.size() != out.x_m.size()) {
        throw InputError(source, line_key(position_line),
                         "has " + std::to_string(positions.size()) + " positions, the first profile " +
                             std::to_string(out.x_m.size()) + ": every profile must be sampled at the same positions");
      }
      // Positions are written rounded; allow a thousandth of the mean step.
      const double tolerance = 1e-3 * (out.x_m.back() - out.x_m.front()) / static_cast<double>(out.x_m.size() - 1);
      for (std::size_t i = 0; i < positions.size(); ++i) {
        if (!(std::abs(positions[i] - out.x_m[i]) <= tolerance)) {
          throw InputError(source, line_key(position_line) + ", field " + std::to_string(i + 2),
                           format_number(positions[i] * 1e3) + " mm differs from the first profile's " +
                               format_number(out.x_m[i] * 1e3) +
                               " mm: every profile must be sampled at the same positions");
        }
      }
    }
    std::size_t dropouts = 0;
    for (double h : heights) dropouts += std::isnan(h) ? 1 : 0;
    if (dropouts == heights.size()) {
      throw InputError(source, line_key(height_line),
                       "every height is a dropout (empty or NaN): the profile has no reading");
    }
    out.dropouts += dropouts;
    out.time_stamps.push_back(stamp);
    out.z_lines.push_back(heights);
  }
  if (out.z_lines.empty()) {
    throw InputError(source, "", "holds no profile: expected pairs of lines (time stamp and positions in mm, then "
                                 "the same time stamp and the heights in mm)");
  }
  return out;
}

LineLaserProfiles read_line_laser_csv(const std::filesystem::path& path) {
  return parse_line_laser_csv(read_text_file(path, line_laser_max_bytes, "line laser file"), path.string());
}

}  // namespace rollnoise
