#include "core/csv.hpp"

#include <cassert>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <ostream>

#include "core/error.hpp"

namespace rollnoise {
namespace {

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    fields.push_back(trim_blanks(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

}  // namespace

std::string_view trim_blanks(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::string printable_excerpt(std::string_view text) {
  std::string out;
  for (char c : text.substr(0, 40)) {
    const auto u = static_cast<unsigned char>(c);
    out += (u >= 0x20 && u < 0x7f) ? c : '?';
  }
  return out;
}

std::size_t NumericCsv::column(const std::string& name, const std::string& source) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  std::string have;
  for (const auto& h : header) have += (have.empty() ? "" : ", ") + h;
  throw InputError(source, "header", "no column \"" + name + "\" (columns are: " + have + ")");
}

NumericCsv parse_numeric_csv(const std::string& text, const std::string& source, EmptyCells empty) {
  NumericCsv csv;
  std::size_t line_number = 0;
  std::size_t pos = 0;
  bool have_header = false;
  while (pos < text.size()) {
    const auto end = text.find('\n', pos);
    std::string_view line(text.data() + pos, (end == std::string::npos ? text.size() : end) - pos);
    pos = end == std::string::npos ? text.size() : end + 1;
    ++line_number;
    if (line_number == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);  // BOM
    const std::string_view content = trim_blanks(line);
    if (content.empty()) continue;
    if (content.front() == '#') {
      csv.comments.emplace_back(content.substr(1));
      continue;
    }
    const std::string where = "line " + std::to_string(line_number);
    auto fields = split(content);
    if (!have_header) {
      for (auto field : fields) {
        if (field.empty()) throw InputError(source, where, "empty column name in the header");
        csv.header.emplace_back(printable_excerpt(field));
      }
      csv.columns.resize(csv.header.size());
      have_header = true;
      continue;
    }
    if (fields.size() != csv.header.size()) {
      throw InputError(source, where,
                       "has " + std::to_string(fields.size()) + " fields, the header has " +
                           std::to_string(csv.header.size()));
    }
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const auto field = fields[c];
      if (field.empty() && empty == EmptyCells::as_nan) {
        csv.columns[c].push_back(std::numeric_limits<double>::quiet_NaN());
        continue;
      }
      double value = 0.0;
      const char* first = field.data();
      const char* last = field.data() + field.size();
      if (first != last && *first == '+') ++first;
      const auto [ptr, ec] = std::from_chars(first, last, value);
      if (field.empty() || ec != std::errc() || ptr != last) {
        throw InputError(source, where + ", column \"" + csv.header[c] + "\"",
                         "\"" + printable_excerpt(field) + "\" is not a number");
      }
      if (!std::isfinite(value)) {
        throw InputError(source, where + ", column \"" + csv.header[c] + "\"",
                         "must be a finite number (got " + printable_excerpt(field) + ")" +
                             (empty == EmptyCells::as_nan ? "; leave the cell empty for a missing value (a dropout)" : ""));
      }
      csv.columns[c].push_back(value);
    }
    csv.row_lines.push_back(line_number);
  }
  if (!have_header) throw InputError(source, "", "no header line (expected column names)");
  return csv;
}

std::optional<double> parse_finite_number(std::string_view text) {
  double value = 0.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (text.empty() || ec != std::errc() || ptr != last || !std::isfinite(value)) return std::nullopt;
  return value;
}

bool is_dropout_cell(std::string_view text) {
  return text.empty() || text == "NaN" || text == "nan" || text == "NAN";
}

std::string read_text_file(const std::filesystem::path& path) {
  return read_text_file(path, std::numeric_limits<std::uintmax_t>::max(), "file");
}

std::string read_text_file(const std::filesystem::path& path, std::uintmax_t max_bytes, const std::string& what) {
  const std::string source = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(source, "", "file not found (or not a regular file)");
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(source, "", "cannot read its size: " + ec.message());
  if (size > max_bytes) {
    throw InputError(source, "", "larger than " + std::to_string(max_bytes >> 20) + " MiB: not a " + what +
                                     " this reader accepts");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(source, "", "cannot be opened for reading");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

NumericCsv read_numeric_csv(const std::filesystem::path& path, EmptyCells empty) {
  return parse_numeric_csv(read_text_file(path), path.string(), empty);
}

std::string format_number(double value) {
  char buffer[32];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, ptr);
}

CsvWriter::CsvWriter(std::ostream& out, const std::vector<std::string>& header)
    : out_(out), columns_(header.size()) {
  for (std::size_t i = 0; i < header.size(); ++i) out_ << (i ? "," : "") << header[i];
  out_ << '\n';
}

void CsvWriter::row(const double* values, std::size_t count) {
  assert(count == columns_);
  line_.clear();
  char buffer[32];
  for (std::size_t i = 0; i < count; ++i) {
    if (i) line_ += ',';
    const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, values[i]);
    line_.append(buffer, ptr);
  }
  line_ += '\n';
  out_ << line_;
}

}  // namespace rollnoise
