#pragma once
// Validators for numeric options whose messages read like the case files' ("must be > 0 (got
// -1)"). CLI11's PositiveNumber and NonNegativeNumber print their range as 0 to DBL_MAX written
// out in full, three hundred digits, and accept infinity and NaN.
#include <cmath>
#include <string>

#include <CLI/CLI.hpp>

namespace rollnoise {

inline CLI::Validator finite_number_at_least(double lowest, bool strictly, const std::string& bound) {
  return CLI::Validator(
      [lowest, strictly, bound](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value))
          return "must be a finite number " + bound + " (got " + text + ")";
        if (strictly ? !(value > lowest) : !(value >= lowest)) return "must be " + bound + " (got " + text + ")";
        return {};
      },
      "NUMBER " + bound);
}

inline CLI::Validator positive_number() { return finite_number_at_least(0.0, true, "> 0"); }
inline CLI::Validator non_negative_number() { return finite_number_at_least(0.0, false, ">= 0"); }

}  // namespace rollnoise
