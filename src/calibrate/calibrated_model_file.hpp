#pragma once
// The calibrated model file: the original model file with the fitted values in place, so that
// its comments (where each value came from) and layout stay, and `rollnoise simulate` reads it
// like the original (ARCHITECTURE.md: a model file holds the keys of a [tyre] table).
#include <string>
#include <utility>
#include <vector>

namespace rollnoise {

// `original`: the model file's text; `values`: top-level keys and their new values;
// `header`: comment lines to put first (each without the leading '#'). Each key's value is
// replaced on its own line (`key = value  # comment`); when a key is not written that way
// (dotted or inline tables), the file is written anew from its parsed table instead, without
// its comments. The result is parsed back and compared with what was asked: any difference is
// an internal error (std::runtime_error). `source` names the original in messages.
std::string calibrated_model_text(const std::string& original, const std::string& source,
                                  const std::vector<std::pair<std::string, double>>& values,
                                  const std::vector<std::string>& header);

// The shortest text that reads back as the same double and that TOML reads as a float
// ("52000.0", "1e+05", "0.08").
std::string toml_float(double value);

}  // namespace rollnoise
