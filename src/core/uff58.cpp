#include "core/uff58.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <system_error>

#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

// ---------------------------------------------------------------------------------------------
// Text helpers

bool is_blank_char(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == '\x1a';
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank_char(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank_char(s.back())) s.remove_suffix(1);
  return s;
}

bool is_blank(std::string_view s) { return trim(s).empty(); }

bool is_delimiter(std::string_view line) { return trim(line) == "-1"; }

bool is_continuation(unsigned char c) { return (c & 0xC0U) == 0x80U; }

// Length of the valid UTF-8 sequence starting at bytes[i] (a non-ASCII lead byte), or 0.
std::size_t utf8_sequence_length(std::string_view bytes, std::size_t i) {
  const auto at = [&](std::size_t k) -> unsigned {
    return i + k < bytes.size() ? static_cast<unsigned char>(bytes[i + k]) : 0U;
  };
  const unsigned c = at(0);
  if (c >= 0xC2 && c <= 0xDF) return is_continuation(static_cast<unsigned char>(at(1))) ? 2 : 0;
  if (c >= 0xE0 && c <= 0xEF) {
    const unsigned c1 = at(1);
    const bool ok1 = (c == 0xE0)   ? (c1 >= 0xA0 && c1 <= 0xBF)
                     : (c == 0xED) ? (c1 >= 0x80 && c1 <= 0x9F)
                                   : is_continuation(static_cast<unsigned char>(c1));
    return ok1 && is_continuation(static_cast<unsigned char>(at(2))) ? 3 : 0;
  }
  if (c >= 0xF0 && c <= 0xF4) {
    const unsigned c1 = at(1);
    const bool ok1 = (c == 0xF0)   ? (c1 >= 0x90 && c1 <= 0xBF)
                     : (c == 0xF4) ? (c1 >= 0x80 && c1 <= 0x8F)
                                   : is_continuation(static_cast<unsigned char>(c1));
    return ok1 && is_continuation(static_cast<unsigned char>(at(2))) &&
                   is_continuation(static_cast<unsigned char>(at(3)))
               ? 4
               : 0;
  }
  return 0;
}

// Valid UTF-8 from the bytes of a text field: valid UTF-8 sequences are kept, other bytes read
// as Latin-1 (0xB2 -> '²'), control characters become '?'.
std::string to_utf8(std::string_view bytes) {
  std::string out;
  out.reserve(bytes.size());
  std::size_t i = 0;
  while (i < bytes.size()) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if (c < 0x80) {
      out += (c < 0x20 && c != '\t') || c == 0x7F ? '?' : static_cast<char>(c);
      ++i;
      continue;
    }
    if (const std::size_t n = utf8_sequence_length(bytes, i); n > 0) {
      out.append(bytes.substr(i, n));
      i += n;
      continue;
    }
    if (c < 0xA0) {
      out += '?';  // C1 control range: no printable Latin-1 character
    } else {
      out += static_cast<char>(0xC0U | (c >> 6U));
      out += static_cast<char>(0x80U | (c & 0x3FU));
    }
    ++i;
  }
  return out;
}

std::string text_field(std::string_view bytes) { return to_utf8(trim(bytes)); }

// A short quotation of input bytes for messages.
std::string quote(std::string_view bytes) {
  constexpr std::size_t max_length = 40;
  bytes = trim(bytes);
  const bool cut = bytes.size() > max_length;
  std::string quoted = "'";  // built by appending: GCC 12 warns (-Wrestrict) on "'" + string
  quoted += to_utf8(bytes.substr(0, max_length));
  quoted += cut ? "...'" : "'";
  return quoted;
}

// ---------------------------------------------------------------------------------------------
// Numbers

std::optional<std::int64_t> parse_integer(std::string_view s) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return value;
}

enum class RealStatus { ok, not_a_number, out_of_range, not_finite };

// Parses the Fortran real at the start of `s` (no leading blanks): optional sign, digits with
// an optional point, an optional exponent written with E, e, D or d. Sets `consumed` to the
// number of characters read.
RealStatus parse_real_prefix(std::string_view s, double& value, std::size_t& consumed) {
  constexpr std::size_t max_length = 64;
  char buffer[max_length];
  std::size_t n = 0;
  std::size_t skipped = 0;
  if (!s.empty() && s.front() == '+') {
    skipped = 1;
    s.remove_prefix(1);
  }
  // Copy the characters a number can be made of, mapping D exponents to E.
  while (n < s.size() && n < max_length) {
    char c = s[n];
    if (c == 'D' || c == 'd') c = 'E';
    const bool allowed = (c >= '0' && c <= '9') || c == '.' || c == 'E' || c == 'e' || c == '+' ||
                         c == '-' || c == 'n' || c == 'N' || c == 'a' || c == 'A' || c == 'i' ||
                         c == 'I' || c == 'f' || c == 'F' || c == 't' || c == 'T' || c == 'y' ||
                         c == 'Y';
    if (!allowed) break;
    buffer[n++] = c;
  }
  if (n == 0) return RealStatus::not_a_number;
  // from_chars does not accept "+" in front of the mantissa but does after the exponent; a
  // leading '+' was removed above, a second sign is not a number.
  if (buffer[0] == '+') return RealStatus::not_a_number;
  const auto [end, ec] = std::from_chars(buffer, buffer + n, value, std::chars_format::general);
  consumed = static_cast<std::size_t>(end - buffer) + skipped;
  if (ec == std::errc::invalid_argument) return RealStatus::not_a_number;
  if (ec == std::errc::result_out_of_range) {
    // Underflow reads as zero; overflow is an error.
    const std::string_view text(buffer, static_cast<std::size_t>(end - buffer));
    const std::size_t e = text.find_first_of("Ee");
    if (e != std::string_view::npos && e + 1 < text.size() && text[e + 1] == '-') {
      value = text.front() == '-' ? -0.0 : 0.0;
      return RealStatus::ok;
    }
    return RealStatus::out_of_range;
  }
  if (!std::isfinite(value)) return RealStatus::not_finite;
  return RealStatus::ok;
}

// ---------------------------------------------------------------------------------------------
// Input cursor

struct Cursor {
  std::string_view data;
  std::size_t pos = 0;
  std::size_t line = 1;  // number of the line that starts at `pos`

  // The line at `pos` without its '\n' and a trailing '\r'; false at the end of the data.
  bool next(std::string_view& text, std::size_t& number) {
    if (pos >= data.size()) return false;
    const std::size_t end = data.find('\n', pos);
    const std::size_t stop = end == std::string_view::npos ? data.size() : end;
    text = data.substr(pos, stop - pos);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    number = line++;
    pos = end == std::string_view::npos ? data.size() : end + 1;
    return true;
  }

  std::size_t remaining() const { return pos < data.size() ? data.size() - pos : 0; }

  // Skips `count` bytes (a binary block), counting the line ends in it.
  void skip_bytes(std::size_t count) {
    const std::string_view block = data.substr(pos, count);
    line += static_cast<std::size_t>(std::count(block.begin(), block.end(), '\n'));
    pos += block.size();
  }
};

// ---------------------------------------------------------------------------------------------
// Dataset context: names the dataset in every message.

class Dataset {
 public:
  Dataset(const std::string& source, std::size_t position, std::size_t line, bool binary)
      : source_(source), position_(position), line_(line), binary_(binary) {}

  [[noreturn]] void fail(std::size_t line, const std::string& where,
                         const std::string& problem) const {
    std::string key = "dataset " + std::to_string(position_) + " (" + (binary_ ? "58b" : "58") +
                      ", line " + std::to_string(line_) + ")";
    if (!where.empty()) key += ", " + where;
    key += ", line " + std::to_string(line);
    throw InputError(source_, key, problem);
  }

 private:
  const std::string& source_;
  std::size_t position_;
  std::size_t line_;
  bool binary_;
};

std::string_view column(std::string_view line, std::size_t begin, std::size_t width) {
  if (begin >= line.size()) return {};
  return line.substr(begin, width);
}

std::vector<std::string_view> split_blanks(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_blank_char(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_blank_char(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
    if (tokens.size() > 64) break;  // header lines have at most a dozen fields
  }
  return tokens;
}

// An integer field of a fixed-format record; blank reads as 0.
struct FixedField {
  const char* name;
  std::size_t begin;
  std::size_t width;
};

std::optional<std::int64_t> fixed_integer(std::string_view line, const FixedField& field) {
  const std::string_view text = trim(column(line, field.begin, field.width));
  if (text.empty()) return 0;
  return parse_integer(text);
}

// Reads every fixed-column integer field into `values`; returns the index of the first field
// that is not an integer, or nullopt when all are.
template <std::size_t N>
std::optional<std::size_t> fixed_integers(std::string_view line, const FixedField (&fields)[N],
                                          std::int64_t (&values)[N]) {
  for (std::size_t i = 0; i < N; ++i) {
    const auto value = fixed_integer(line, fields[i]);
    if (!value) return i;
    values[i] = *value;
  }
  return std::nullopt;
}

int narrow_small(std::int64_t value, const Dataset& ds, std::size_t line, const std::string& where,
                 const char* name) {
  if (value < -99999 || value > 99999)
    ds.fail(line, where, std::string(name) + " " + std::to_string(value) + " is out of range");
  return static_cast<int>(value);
}

// Record 6: Format(2(I5,I10),2(1X,10A1,I10,I4)).
void parse_record6(std::string_view line, std::size_t number, const Dataset& ds, Uff58Record& r) {
  static constexpr FixedField fields[] = {
      {"function type", 0, 5},    {"function identification number", 5, 10},
      {"version number", 15, 5},  {"load case", 20, 10},
      {"response node", 41, 10},  {"response direction", 51, 4},
      {"reference node", 66, 10}, {"reference direction", 76, 4}};
  std::int64_t v[8] = {};
  const std::optional<std::size_t> first_bad = fixed_integers(line, fields, v);
  const bool fixed_ok = !first_bad;
  const std::size_t bad = first_bad.value_or(0);
  if (fixed_ok) {
    r.response_entity = text_field(column(line, 31, 10));
    r.reference_entity = text_field(column(line, 56, 10));
  } else {
    // Some writers do not keep the columns: ten blank-separated fields with one-word names.
    const auto tokens = split_blanks(line);
    bool tokens_ok = tokens.size() == 10;
    static constexpr std::size_t integer_tokens[8] = {0, 1, 2, 3, 5, 6, 8, 9};
    for (std::size_t i = 0; tokens_ok && i < 8; ++i) {
      const auto value = parse_integer(tokens[integer_tokens[i]]);
      if (!value)
        tokens_ok = false;
      else
        v[i] = *value;
    }
    if (!tokens_ok) {
      const FixedField& f = fields[bad];
      ds.fail(number, "record 6",
              std::string(f.name) + " (columns " + std::to_string(f.begin + 1) + "-" +
                  std::to_string(f.begin + f.width) +
                  "): " + quote(column(line, f.begin, f.width)) +
                  " is not an integer (record 6 is Format(2(I5,I10),2(1X,10A1,I10,I4)))");
    }
    r.response_entity = text_field(tokens[4]);
    r.reference_entity = text_field(tokens[7]);
  }
  const std::string where = "record 6";
  r.function_type = narrow_small(v[0], ds, number, where, "function type");
  if (r.function_type < 0)
    ds.fail(number, where, "function type " + std::to_string(r.function_type) + " is negative");
  r.function_id = v[1];
  r.version_number = v[2];
  r.load_case = v[3];
  r.response_node = v[4];
  r.response_direction = narrow_small(v[5], ds, number, where, "response direction");
  r.reference_node = v[6];
  r.reference_direction = narrow_small(v[7], ds, number, where, "reference direction");
}

// Scans the blank-separated (or touching) reals of `text` into `out`. Returns false and sets
// `problem` on the first thing that is not a finite real.
bool scan_reals(std::string_view text, std::vector<double>& out, std::size_t limit,
                std::string& problem) {
  std::size_t i = 0;
  while (i < text.size()) {
    if (is_blank_char(text[i])) {
      ++i;
      continue;
    }
    double value = 0.0;
    std::size_t consumed = 0;
    const RealStatus status = parse_real_prefix(text.substr(i), value, consumed);
    std::size_t end = i + consumed;
    if (status == RealStatus::ok) {
      // A number ends at a blank, at the end of the line or where the next signed one begins.
      if (end < text.size() && !is_blank_char(text[end]) && text[end] != '-' && text[end] != '+') {
        std::size_t stop = end;
        while (stop < text.size() && !is_blank_char(text[stop])) ++stop;
        problem = quote(text.substr(i, stop - i)) + " is not a number";
        return false;
      }
      if (out.size() >= limit) {
        problem = "more values than declared";
        return false;
      }
      out.push_back(value);
      i = end;
      continue;
    }
    std::size_t stop = i;
    while (stop < text.size() && !is_blank_char(text[stop])) ++stop;
    const std::string token = quote(text.substr(i, stop - i));
    if (status == RealStatus::out_of_range)
      problem = token + " is out of the range of a double";
    else if (status == RealStatus::not_finite)
      problem = token + " is not a finite number";
    else
      problem = token + " is not a number";
    return false;
  }
  return true;
}

// Record 7: Format(3I10,3E13.5).
void parse_record7(std::string_view line, std::size_t number, const Dataset& ds, Uff58Record& r) {
  const std::string where = "record 7";
  // Three integers, then the reals (which may touch each other).
  std::size_t i = 0;
  std::int64_t ints[3] = {};
  static constexpr const char* names[3] = {"ordinate data type", "number of points",
                                           "abscissa spacing"};
  for (std::size_t k = 0; k < 3; ++k) {
    while (i < line.size() && is_blank_char(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_blank_char(line[i])) ++i;
    const std::string_view token = line.substr(start, i - start);
    if (token.empty())
      ds.fail(number, where,
              std::string("the ") + names[k] +
                  " is missing (record 7 is Format(3I10,3E13.5): ordinate data type, number of "
                  "points, abscissa spacing, abscissa minimum, increment, z-axis value)");
    const auto value = parse_integer(token);
    if (!value)
      ds.fail(number, where, std::string(names[k]) + ": " + quote(token) + " is not an integer");
    ints[k] = *value;
  }
  std::vector<double> reals;
  std::string problem;
  if (!scan_reals(line.substr(i), reals, 3, problem)) {
    if (problem == "more values than declared")
      problem = "more than the 6 fields of Format(3I10,3E13.5)";
    ds.fail(number, where, problem);
  }
  if (reals.size() < 2)
    ds.fail(number, where,
            "the abscissa minimum and increment are missing (record 7 is Format(3I10,3E13.5))");

  switch (ints[0]) {
    case 2:
      r.ordinate_type = UffOrdinateType::real_single;
      break;
    case 4:
      r.ordinate_type = UffOrdinateType::real_double;
      break;
    case 5:
      r.ordinate_type = UffOrdinateType::complex_single;
      break;
    case 6:
      r.ordinate_type = UffOrdinateType::complex_double;
      break;
    default:
      ds.fail(number, where,
              "ordinate data type " + std::to_string(ints[0]) +
                  " is not one of 2 (real single), 4 (real double), 5 (complex single), 6 "
                  "(complex double)");
  }
  if (ints[1] < 1)
    ds.fail(number, where, "number of points " + std::to_string(ints[1]) + " is not positive");
  r.points = static_cast<std::size_t>(ints[1]);
  if (ints[2] != 0 && ints[2] != 1)
    ds.fail(number, where,
            "abscissa spacing " + std::to_string(ints[2]) + " is not 0 (uneven) or 1 (even)");
  r.even_spacing = ints[2] == 1;
  r.abscissa_min = reals[0];
  r.abscissa_increment = reals[1];
  r.z_axis_value = reals.size() > 2 ? reals[2] : 0.0;
  if (r.even_spacing && !(r.abscissa_increment > 0.0))
    ds.fail(number, where,
            "abscissa increment " + format_number(r.abscissa_increment) +
                " must be positive for even spacing");
}

// Records 8-11: Format(I10,3I5,2(1X,20A1)).
void parse_axis(std::string_view line, std::size_t number, int record, const Dataset& ds,
                UffAxis& axis) {
  static constexpr FixedField fields[] = {{"specific data type", 0, 10},
                                          {"length units exponent", 10, 5},
                                          {"force units exponent", 15, 5},
                                          {"temperature units exponent", 20, 5}};
  const std::string where = "record " + std::to_string(record);
  std::int64_t v[4] = {};
  const std::optional<std::size_t> first_bad = fixed_integers(line, fields, v);
  const bool fixed_ok = !first_bad;
  const std::size_t bad = first_bad.value_or(0);
  if (fixed_ok) {
    axis.label = text_field(column(line, 26, 20));
    // The units label is the last field: take the rest of the line, so a multi-byte character
    // that pushed it to the right is not cut.
    axis.units = text_field(column(line, 47, std::string_view::npos));
  } else {
    const auto tokens = split_blanks(line);
    bool tokens_ok = tokens.size() >= 4 && tokens.size() <= 6;
    for (std::size_t i = 0; tokens_ok && i < 4; ++i) {
      const auto value = parse_integer(tokens[i]);
      if (!value)
        tokens_ok = false;
      else
        v[i] = *value;
    }
    if (!tokens_ok) {
      const FixedField& f = fields[bad];
      ds.fail(number, where,
              std::string(f.name) + " (columns " + std::to_string(f.begin + 1) + "-" +
                  std::to_string(f.begin + f.width) +
                  "): " + quote(column(line, f.begin, f.width)) +
                  " is not an integer (records 8-11 are Format(I10,3I5,2(1X,20A1)))");
    }
    axis.label = tokens.size() > 4 ? text_field(tokens[4]) : std::string("NONE");
    axis.units = tokens.size() > 5 ? text_field(tokens[5]) : std::string("NONE");
  }
  axis.specific_data_type = narrow_small(v[0], ds, number, where, "specific data type");
  axis.length_exponent = narrow_small(v[1], ds, number, where, "length units exponent");
  axis.force_exponent = narrow_small(v[2], ds, number, where, "force units exponent");
  axis.temperature_exponent = narrow_small(v[3], ds, number, where, "temperature units exponent");
}

std::size_t values_per_point(const Uff58Record& r) {
  return (r.is_complex() ? 2U : 1U) + (r.even_spacing ? 0U : 1U);
}

bool single_precision(const Uff58Record& r) {
  return r.ordinate_type == UffOrdinateType::real_single ||
         r.ordinate_type == UffOrdinateType::complex_single;
}

// Fills abscissa and ordinate from the flat values; `x` holds the uneven abscissa (or is
// empty), `y` the ordinate values (1 or 2 per point).
void fill_data(Uff58Record& r, const std::vector<double>& x, const std::vector<double>& y) {
  const auto n = static_cast<Eigen::Index>(r.points);
  r.abscissa.resize(n);
  if (r.even_spacing) {
    for (Eigen::Index k = 0; k < n; ++k)
      r.abscissa[k] = r.abscissa_min + static_cast<double>(k) * r.abscissa_increment;
  } else {
    for (Eigen::Index k = 0; k < n; ++k) r.abscissa[k] = x[static_cast<std::size_t>(k)];
  }
  if (r.is_complex()) {
    r.complex_ordinate.resize(n);
    for (Eigen::Index k = 0; k < n; ++k)
      r.complex_ordinate[k] = {y[2 * static_cast<std::size_t>(k)],
                               y[2 * static_cast<std::size_t>(k) + 1]};
  } else {
    r.ordinate.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) r.ordinate[k] = y[static_cast<std::size_t>(k)];
  }
}

// Splits interleaved values (x, y...) per point.
void split_interleaved(const Uff58Record& r, const std::vector<double>& values,
                       std::vector<double>& x, std::vector<double>& y) {
  const std::size_t per = values_per_point(r);
  const std::size_t ordinate_values = r.is_complex() ? 2 : 1;
  x.clear();
  y.clear();
  y.reserve(r.points * ordinate_values);
  if (!r.even_spacing) x.reserve(r.points);
  for (std::size_t k = 0; k < r.points; ++k) {
    const std::size_t base = k * per;
    std::size_t j = 0;
    if (!r.even_spacing) x.push_back(values[base + j++]);
    for (std::size_t m = 0; m < ordinate_values; ++m) y.push_back(values[base + j++]);
  }
}

// The closing "-1" of a dataset; the end of the file is accepted in its place once the data
// is complete. Blank lines before it are skipped.
void expect_closing(Cursor& cursor, const Dataset& ds, const char* after) {
  std::string_view line;
  std::size_t number = 0;
  while (cursor.next(line, number)) {
    if (is_blank(line)) continue;
    if (is_delimiter(line)) return;
    ds.fail(number, "",
            std::string("expected the line '    -1' that closes the dataset ") + after +
                ", found " + quote(line));
  }
}

void parse_ascii_data(Cursor& cursor, const Dataset& ds, std::size_t header_end_line,
                      Uff58Record& r) {
  const std::size_t per = values_per_point(r);
  const std::size_t expected = r.points * per;  // points <= remaining bytes: no overflow
  std::vector<double> values;
  values.reserve(std::min(expected, cursor.remaining() / 2 + 1));
  std::string_view line;
  std::size_t number = header_end_line;
  bool closed = false;
  while (cursor.next(line, number)) {
    if (is_delimiter(line)) {
      closed = true;
      break;
    }
    std::string problem;
    if (!scan_reals(line, values, expected, problem)) {
      if (problem == "more values than declared")
        problem = "more data values than the " + std::to_string(r.points) +
                  " points declared in record 7 (" + std::to_string(expected) + " values)";
      ds.fail(number, "data", problem);
    }
  }
  if (values.size() < expected) {
    ds.fail(number, "data",
            std::string(closed ? "the dataset closes" : "the file ends") + " after " +
                std::to_string(values.size()) + " of the " + std::to_string(expected) +
                " data values that record 7 declares (" + std::to_string(r.points) + " points, " +
                std::to_string(per) + " value" + (per > 1 ? "s" : "") + " each)");
  }
  std::vector<double> x, y;
  split_interleaved(r, values, x, y);
  fill_data(r, x, y);
}

struct BinaryFormat {
  bool little_endian = true;
  std::size_t bytes = 0;
};

std::uint32_t byteswap32(std::uint32_t v) {
  return ((v & 0xFFU) << 24U) | ((v & 0xFF00U) << 8U) | ((v >> 8U) & 0xFF00U) | (v >> 24U);
}

std::uint64_t byteswap64(std::uint64_t v) {
  return (static_cast<std::uint64_t>(byteswap32(static_cast<std::uint32_t>(v))) << 32U) |
         byteswap32(static_cast<std::uint32_t>(v >> 32U));
}

double decode(const char* p, std::size_t size, bool swap) {
  if (size == 4) {
    std::uint32_t u = 0;
    std::memcpy(&u, p, 4);
    if (swap) u = byteswap32(u);
    return static_cast<double>(std::bit_cast<float>(u));
  }
  std::uint64_t u = 0;
  std::memcpy(&u, p, 8);
  if (swap) u = byteswap64(u);
  return std::bit_cast<double>(u);
}

void parse_binary_data(Cursor& cursor, const Dataset& ds, const BinaryFormat& format,
                       std::size_t header_end_line, Uff58Record& r) {
  const std::size_t per = values_per_point(r);
  const std::size_t size = single_precision(r) ? 4 : 8;
  const std::size_t expected = r.points * per * size;  // points <= remaining bytes
  // For uneven double-precision data, the specification's abscissa is single precision.
  const std::size_t mixed = (!r.even_spacing && size == 8) ? r.points * (4 + (per - 1) * 8) : 0;
  const std::size_t data_line = header_end_line + 1;
  if (format.bytes > cursor.remaining())
    ds.fail(data_line, "binary data",
            "the 58b header declares " + std::to_string(format.bytes) +
                " bytes of binary data, but only " + std::to_string(cursor.remaining()) +
                " bytes are left in the file");
  const bool abscissa_single = mixed != 0 && format.bytes == mixed;
  if (format.bytes != expected && !abscissa_single)
    ds.fail(data_line, "binary data",
            "the 58b header declares " + std::to_string(format.bytes) + " bytes, but " +
                std::to_string(r.points) + " points of " + uff_ordinate_type_name(r.ordinate_type) +
                (r.even_spacing ? "" : " with uneven abscissa") + " take " +
                std::to_string(expected) + " bytes");
  const bool swap = format.little_endian != (std::endian::native == std::endian::little);
  const char* p = cursor.data.data() + cursor.pos;
  const std::size_t ordinate_values = r.is_complex() ? 2 : 1;
  std::vector<double> x, y;
  if (!r.even_spacing) x.reserve(r.points);
  y.reserve(r.points * ordinate_values);
  std::size_t offset = 0;
  for (std::size_t k = 0; k < r.points; ++k) {
    for (std::size_t j = 0; j < per; ++j) {
      const bool is_abscissa = !r.even_spacing && j == 0;
      const std::size_t width = is_abscissa && abscissa_single ? 4 : size;
      const double value = decode(p + offset, width, swap);
      if (!std::isfinite(value))
        ds.fail(data_line, "binary data",
                "value " + std::to_string(k * per + j + 1) + " (point " + std::to_string(k + 1) +
                    ", byte offset " + std::to_string(offset) + ") is not a finite number");
      (is_abscissa ? x : y).push_back(value);
      offset += width;
    }
  }
  cursor.skip_bytes(format.bytes);
  fill_data(r, x, y);
}

std::string_view::size_type find_dataset_number(std::string_view token, int& number, bool& binary) {
  std::size_t digits = 0;
  while (digits < token.size() && token[digits] >= '0' && token[digits] <= '9') ++digits;
  if (digits == 0 || digits > 9) return std::string_view::npos;
  const std::string_view rest = token.substr(digits);
  if (!rest.empty() && rest != "b" && rest != "B") return std::string_view::npos;
  binary = !rest.empty();
  std::int64_t value = 0;
  for (std::size_t i = 0; i < digits; ++i) value = value * 10 + (token[i] - '0');
  number = static_cast<int>(value);
  return digits;
}

// Parses one dataset 58/58b whose number line is `number_line`; the cursor stands after it.
Uff58Record parse_dataset58(Cursor& cursor, const std::string& source, std::size_t position,
                            std::size_t start_line, bool binary, std::string_view number_line,
                            std::size_t number_line_no) {
  const Dataset ds(source, position, start_line, binary);
  Uff58Record r;
  r.position = position;
  r.line = start_line;
  r.binary = binary;

  BinaryFormat format;
  if (binary) {
    // Format(I6,1A1,I6,I6,I12,I12,I6,I6,I12,I12): 58b, byte ordering, floating-point format,
    // number of ASCII lines, number of bytes, unused fields.
    const auto tokens = split_blanks(number_line);
    const std::string where = "58b header";
    if (tokens.size() < 5)
      ds.fail(number_line_no, where,
              "the 58b line needs byte ordering, floating-point format, number of ASCII lines "
              "and number of binary bytes after '58b', found " +
                  quote(number_line));
    std::int64_t v[4] = {};
    static constexpr const char* names[4] = {"byte ordering", "floating-point format",
                                             "number of ASCII lines", "number of bytes"};
    for (std::size_t i = 0; i < 4; ++i) {
      const auto value = parse_integer(tokens[i + 1]);
      if (!value)
        ds.fail(number_line_no, where,
                std::string(names[i]) + ": " + quote(tokens[i + 1]) + " is not an integer");
      v[i] = *value;
    }
    if (v[0] != 1 && v[0] != 2)
      ds.fail(
          number_line_no, where,
          "byte ordering " + std::to_string(v[0]) + " is not 1 (little endian) or 2 (big endian)");
    if (v[1] != 2) {
      const std::string what = v[1] == 1   ? " (DEC VMS) is not supported"
                               : v[1] == 3 ? " (IBM 5/370) is not supported"
                                           : " is not a known format";
      ds.fail(
          number_line_no, where,
          "floating-point format " + std::to_string(v[1]) + what + "; only 2 (IEEE 754) is read");
    }
    if (v[2] != 11)
      ds.fail(number_line_no, where,
              "the 58b header declares " + std::to_string(v[2]) +
                  " ASCII header lines; dataset 58 has 11");
    if (v[3] < 0)
      ds.fail(number_line_no, where, "number of bytes " + std::to_string(v[3]) + " is negative");
    format.little_endian = v[0] == 1;
    format.bytes = static_cast<std::size_t>(v[3]);
  }

  std::string_view lines[11];
  std::size_t numbers[11] = {};
  for (std::size_t k = 0; k < 11; ++k) {
    if (!cursor.next(lines[k], numbers[k]))
      ds.fail(cursor.line, "record " + std::to_string(k + 1),
              "the file ends in the header (record " + std::to_string(k + 1) +
                  " of the 11 header records is missing)");
    if (is_delimiter(lines[k]))
      ds.fail(numbers[k], "record " + std::to_string(k + 1),
              "the dataset closes in its header (record " + std::to_string(k + 1) +
                  " of the 11 header records is missing)");
  }
  for (std::size_t k = 0; k < 5; ++k) r.id_lines[k] = text_field(lines[k]);
  parse_record6(lines[5], numbers[5], ds, r);
  parse_record7(lines[6], numbers[6], ds, r);
  parse_axis(lines[7], numbers[7], 8, ds, r.abscissa_axis);
  parse_axis(lines[8], numbers[8], 9, ds, r.numerator_axis);
  parse_axis(lines[9], numbers[9], 10, ds, r.denominator_axis);
  parse_axis(lines[10], numbers[10], 11, ds, r.z_axis);

  // Each value takes at least one byte (four in binary): a corrupt count cannot make us
  // allocate more than the file can fill.
  const std::size_t per = values_per_point(r);
  const std::size_t min_bytes = binary ? 4 : 1;
  if (r.points > cursor.remaining() / (per * min_bytes))
    ds.fail(numbers[6], "record 7",
            "number of points " + std::to_string(r.points) + " (" + std::to_string(per) + " value" +
                (per > 1 ? "s" : "") + " each) cannot fit in the " +
                std::to_string(cursor.remaining()) + " bytes left in the file");

  if (binary) {
    parse_binary_data(cursor, ds, format, numbers[10], r);
    expect_closing(cursor, ds, "after its binary data");
  } else {
    parse_ascii_data(cursor, ds, numbers[10], r);
  }
  return r;
}

}  // namespace

std::vector<Uff58Record> parse_uff58(std::string_view bytes, const std::string& source,
                                     std::vector<int>* skipped_datasets) {
  if (skipped_datasets) skipped_datasets->clear();
  std::vector<Uff58Record> records;
  Cursor cursor{bytes, 0, 1};
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") cursor.pos = 3;  // UTF-8 byte order mark

  std::size_t datasets = 0;
  std::string_view line;
  std::size_t number = 0;
  while (cursor.next(line, number)) {
    if (is_blank(line)) continue;
    if (!is_delimiter(line)) {
      if (datasets == 0)
        throw InputError(source, "line " + std::to_string(number),
                         "not a UFF file: expected the line '    -1' that opens a dataset, "
                         "found " +
                             quote(line));
      throw InputError(source, "line " + std::to_string(number),
                       "expected the line '    -1' that opens the next dataset (after dataset " +
                           std::to_string(datasets) + "), found " + quote(line));
    }
    std::size_t start_line = number;
    // The dataset number; a lone "-1" at the end of the file (or repeated "-1") is tolerated.
    std::string_view number_line;
    std::size_t number_line_no = 0;
    bool have_number = false;
    while (cursor.next(number_line, number_line_no)) {
      if (is_blank(number_line)) continue;
      if (is_delimiter(number_line)) {
        start_line = number_line_no;
        continue;
      }
      have_number = true;
      break;
    }
    if (!have_number) break;

    ++datasets;
    const auto tokens = split_blanks(number_line);
    int dataset_number = 0;
    bool binary = false;
    if (tokens.empty() ||
        find_dataset_number(tokens.front(), dataset_number, binary) == std::string_view::npos)
      throw InputError(source,
                       "dataset " + std::to_string(datasets) + " (line " +
                           std::to_string(start_line) + "), line " + std::to_string(number_line_no),
                       "expected a dataset number (such as 58 or 58b) after the line '    -1', "
                       "found " +
                           quote(number_line));

    if (dataset_number == 58) {
      records.push_back(parse_dataset58(cursor, source, datasets, start_line, binary, number_line,
                                        number_line_no));
      continue;
    }
    if (skipped_datasets) skipped_datasets->push_back(dataset_number);
    // Skip to the closing "-1" (or the end of the file).
    std::string_view skipped;
    std::size_t skipped_no = 0;
    while (cursor.next(skipped, skipped_no))
      if (is_delimiter(skipped)) break;
  }
  if (datasets == 0)
    throw InputError(source, "",
                     "not a UFF file: no dataset found (a UFF file is a sequence of datasets, "
                     "each between lines holding '    -1')");
  return records;
}

std::vector<Uff58Record> read_uff58(const std::filesystem::path& path,
                                    std::vector<int>* skipped_datasets) {
  const std::string source = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(source, "", "cannot open the file for reading");
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError(source, "", "cannot read the file");
  return parse_uff58(bytes, source, skipped_datasets);
}

std::string uff_function_type_name(int function_type) {
  static constexpr const char* names[] = {"general or unknown",
                                          "time response",
                                          "auto spectrum",
                                          "cross spectrum",
                                          "frequency response function",
                                          "transmissibility",
                                          "coherence",
                                          "auto correlation",
                                          "cross correlation",
                                          "power spectral density (PSD)",
                                          "energy spectral density (ESD)",
                                          "probability density function",
                                          "spectrum",
                                          "cumulative frequency distribution",
                                          "peaks valley",
                                          "stress/cycles",
                                          "strain/cycles",
                                          "orbit",
                                          "mode indicator function",
                                          "force pattern",
                                          "partial power",
                                          "partial coherence",
                                          "eigenvalue",
                                          "eigenvector",
                                          "shock response spectrum",
                                          "finite impulse response filter",
                                          "multiple coherence",
                                          "order function",
                                          "phase compensation"};
  constexpr int count = static_cast<int>(sizeof names / sizeof names[0]);
  if (function_type >= 0 && function_type < count) return names[function_type];
  return "function type " + std::to_string(function_type);
}

std::string uff_specific_data_type_name(int specific_data_type) {
  switch (specific_data_type) {
    case 0:
      return "unknown";
    case 1:
      return "general";
    case 2:
      return "stress";
    case 3:
      return "strain";
    case 5:
      return "temperature";
    case 6:
      return "heat flux";
    case 8:
      return "displacement";
    case 9:
      return "reaction force";
    case 11:
      return "velocity";
    case 12:
      return "acceleration";
    case 13:
      return "excitation force";
    case 15:
      return "pressure";
    case 16:
      return "mass";
    case 17:
      return "time";
    case 18:
      return "frequency";
    case 19:
      return "rpm";
    case 20:
      return "order";
    case 21:
      return "sound pressure";
    case 22:
      return "sound intensity";
    case 23:
      return "sound power";
    default:
      return "specific data type " + std::to_string(specific_data_type);
  }
}

std::string uff_ordinate_type_name(UffOrdinateType type) {
  switch (type) {
    case UffOrdinateType::real_single:
      return "real single precision";
    case UffOrdinateType::real_double:
      return "real double precision";
    case UffOrdinateType::complex_single:
      return "complex single precision";
    case UffOrdinateType::complex_double:
      return "complex double precision";
  }
  return "ordinate data type " + std::to_string(static_cast<int>(type));
}

std::string describe_uff58(const Uff58Record& r) {
  std::ostringstream out;
  out.precision(6);
  out << "dataset " << r.position << " (" << (r.binary ? "58b" : "58") << ", line " << r.line
      << "): " << uff_function_type_name(r.function_type) << " (function type " << r.function_type
      << "), " << r.points << " points, " << uff_ordinate_type_name(r.ordinate_type);
  if (r.even_spacing)
    out << ", even abscissa " << r.abscissa_min << " + k*" << r.abscissa_increment;
  else
    out << ", uneven abscissa";
  if (!r.abscissa_axis.units.empty() && r.abscissa_axis.units != "NONE")
    out << " " << r.abscissa_axis.units;
  if (!r.numerator_axis.units.empty() && r.numerator_axis.units != "NONE") {
    out << ", ordinate " << r.numerator_axis.units;
    if (!r.denominator_axis.units.empty() && r.denominator_axis.units != "NONE")
      out << " / " << r.denominator_axis.units;
  }
  if (!r.id_lines[0].empty() && r.id_lines[0] != "NONE") out << ", '" << r.id_lines[0] << "'";
  return out.str();
}

}  // namespace rollnoise
