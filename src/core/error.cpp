#include "core/error.hpp"

namespace rollnoise {

std::string format_input_error(const std::string& source, const std::string& key,
                               const std::string& problem) {
  std::string message;
  if (!source.empty()) message += source + ": ";
  if (!key.empty()) message += key + ": ";
  return message + problem;
}

InputError::InputError(std::string source, std::string key, std::string problem)
    : std::runtime_error(format_input_error(source, key, problem)),
      source_(std::move(source)),
      key_(std::move(key)),
      problem_(std::move(problem)) {}

InputError InputError::with_source(const std::string& source) const {
  if (!source_.empty()) return *this;
  return InputError(source, key_, problem_);
}

}  // namespace rollnoise
