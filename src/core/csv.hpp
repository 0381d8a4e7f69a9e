#pragma once
// Numeric CSV files: a header line of column names, then rows of numbers. Lines starting
// with '#' are comments. Readers survive arbitrary bytes: anything else is an InputError
// naming the file, line and column.
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rollnoise {

struct NumericCsv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> columns;  // columns[c][row]
  std::vector<std::string> comments;         // comment lines, without the leading '#'
  std::vector<std::size_t> row_lines;        // the line number (from 1) of each data row

  std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
  // Index of a column by name; InputError (naming `source`) when absent.
  std::size_t column(const std::string& name, const std::string& source) const;
};

// What a data cell may hold besides a finite number.
enum class EmptyCells {
  reject,   // an empty cell is an InputError (the default)
  as_nan,   // an empty cell (nothing but blanks between the commas) reads as NaN: a measurement
            // with no value, such as a profilometer dropout. Text such as "nan" is still rejected.
};

// Parses CSV text; `source` names it in messages. Non-finite values are rejected.
NumericCsv parse_numeric_csv(const std::string& text, const std::string& source,
                             EmptyCells empty = EmptyCells::reject);
NumericCsv read_numeric_csv(const std::filesystem::path& path, EmptyCells empty = EmptyCells::reject);
// The whole content of a file; InputError naming it when it is missing or unreadable.
std::string read_text_file(const std::filesystem::path& path);
// The same, for a reader that takes at most `max_bytes`: a larger file is an InputError ("larger
// than N MiB: not a `what` this reader accepts"), told from its size before it is read.
std::string read_text_file(const std::filesystem::path& path, std::uintmax_t max_bytes, const std::string& what);

// A finite number written in full (a leading '+' allowed), or nothing: text that is empty, not a
// number, followed by anything, or infinite or NaN.
std::optional<double> parse_finite_number(std::string_view text);
// A cell that marks a missing reading in measured profiles: empty, or NaN as instruments write it.
bool is_dropout_cell(std::string_view text);

// `text` without leading and trailing blanks, tabs and carriage returns.
std::string_view trim_blanks(std::string_view text);
// The first 40 bytes of `text` with anything but printable ASCII shown as '?': for quoting
// untrusted input in a message.
std::string printable_excerpt(std::string_view text);

// The shortest text that reads back as exactly the same double.
std::string format_number(double value);

// Writes rows of numbers with a header, shortest round-trip formatting.
class CsvWriter {
 public:
  CsvWriter(std::ostream& out, const std::vector<std::string>& header);
  void row(const double* values, std::size_t count);

 private:
  std::ostream& out_;
  std::size_t columns_;
  std::string line_;
};

}  // namespace rollnoise
