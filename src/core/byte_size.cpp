#include "core/byte_size.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace rollnoise {

std::optional<std::uint64_t> parse_byte_size(const std::string& text) {
  const char* begin = text.c_str();
  while (std::isspace(static_cast<unsigned char>(*begin))) ++begin;
  // Digits and a point only: strtod would also take "inf", "nan" and hexadecimal.
  const char* digits = begin;
  while (std::isdigit(static_cast<unsigned char>(*digits)) || *digits == '.') ++digits;
  if (digits == begin) return std::nullopt;
  char* end = nullptr;
  const double number = std::strtod(begin, &end);
  if (end != digits || !(number > 0.0)) return std::nullopt;
  // The unit: what follows, without the spaces around it.
  std::string unit(end);
  unit.erase(0, unit.find_first_not_of(" \t"));
  unit.erase(unit.find_last_not_of(" \t") + 1);
  for (char& c : unit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  static const std::pair<const char*, double> units[] = {
      {"", 1.0},      {"b", 1.0},       {"kb", 1e3},           {"mb", 1e6},           {"gb", 1e9},
      {"tb", 1e12},   {"kib", 1024.0},  {"mib", 1048576.0},    {"gib", 1073741824.0}, {"tib", 1099511627776.0}};
  for (const auto& [name, scale] : units) {
    if (unit != name) continue;
    const double bytes = std::floor(number * scale);
    if (!(bytes >= 1.0) || !(bytes < 1.8e19)) return std::nullopt;
    return static_cast<std::uint64_t>(bytes);
  }
  return std::nullopt;
}

}  // namespace rollnoise
