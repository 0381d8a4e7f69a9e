#include "calibrate/calibrated_model_file.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <toml++/toml.h>

#include "core/csv.hpp"

namespace rollnoise {
namespace {

bool is_key_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

// Replaces the value of `key` on its top-level line; false unless exactly one such line exists.
bool replace_on_its_line(std::vector<std::string>& lines, const std::string& key, const std::string& value) {
  std::size_t found = 0;
  std::size_t at_line = 0, value_begin = 0, value_end = 0;
  bool top_level = true;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    std::size_t p = line.find_first_not_of(" \t");
    if (p == std::string::npos || line[p] == '#') continue;
    if (line[p] == '[') {
      top_level = false;  // a [table] or [[array]] header: what follows is not top level
      continue;
    }
    if (!top_level) continue;
    std::size_t q = p;
    while (q < line.size() && is_key_char(line[q])) ++q;
    if (line.compare(p, q - p, key) != 0 || q - p != key.size()) continue;
    std::size_t eq = line.find_first_not_of(" \t", q);
    if (eq == std::string::npos || line[eq] != '=') continue;
    const std::size_t begin = line.find_first_not_of(" \t", eq + 1);
    if (begin == std::string::npos) return false;
    std::size_t end = line.find('#', begin);
    if (end == std::string::npos) end = line.size();
    while (end > begin && (line[end - 1] == ' ' || line[end - 1] == '\t' || line[end - 1] == '\r')) --end;
    ++found;
    at_line = i;
    value_begin = begin;
    value_end = end;
  }
  if (found != 1) return false;
  std::string& line = lines[at_line];
  std::string replaced = line.substr(0, value_begin);
  replaced += value;
  // Keep a trailing comment in its column where the blanks before it leave room.
  const std::size_t old_length = value_end - value_begin;
  std::string rest = line.substr(value_end);
  if (value.size() < old_length && !rest.empty()) {
    replaced.append(old_length - value.size(), ' ');
  } else if (value.size() > old_length) {
    const std::size_t blanks = rest.find_first_not_of(' ');
    if (blanks != std::string::npos && blanks > 1)
      rest.erase(0, std::min(blanks - 1, value.size() - old_length));
  }
  replaced += rest;
  line = replaced;
  return true;
}

}  // namespace

std::string toml_float(double value) {
  std::string text = format_number(value);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";  // "52000" would read as an integer
  return text;
}

std::string calibrated_model_text(const std::string& original, const std::string& source,
                                  const std::vector<std::pair<std::string, double>>& values,
                                  const std::vector<std::string>& header) {
  const toml::table parsed = toml::parse(original, source);
  std::vector<std::string> lines;
  {
    std::istringstream in(original);
    std::string line;
    while (std::getline(in, line)) lines.push_back(line);
  }
  bool in_place = true;
  for (const auto& [key, value] : values) in_place = in_place && replace_on_its_line(lines, key, toml_float(value));

  std::string body;
  if (in_place) {
    for (const std::string& line : lines) {
      body += line;
      body += '\n';
    }
  } else {
    toml::table table = parsed;
    for (const auto& [key, value] : values) table.insert_or_assign(key, value);
    std::ostringstream out;
    out << toml::toml_formatter(table) << '\n';
    body = out.str();
  }
  std::string text;
  for (const std::string& h : header) {
    text += '#';
    if (!h.empty()) text += ' ';
    text += h;
    text += '\n';
  }
  text += body;

  // Read it back: the asked values exactly, everything else as it was.
  toml::table expected = parsed;
  for (const auto& [key, value] : values) expected.insert_or_assign(key, value);
  const toml::table written = toml::parse(text, source);
  if (!(written == expected))
    throw std::runtime_error("calibrate: the calibrated model file does not read back as the fitted model (" + source +
                             ")");
  return text;
}

}  // namespace rollnoise
