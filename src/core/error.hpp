#pragma once
// Error types. Bad input (a case file, a data file, a command-line value, a physically
// meaningless setting) is an InputError and ends the program with exit status 2; anything
// else that escapes is an internal failure (exit status 1).
#include <stdexcept>
#include <string>

namespace rollnoise {

class InputError : public std::runtime_error {
 public:
  // source: the file (or "--set", "command line") the bad value came from; may be empty when
  // the thrower cannot know it, and the caller fills it in with with_source().
  // key: where in the source, such as "[tyre] mass" or "line 12"; problem: what is wrong and
  // what is allowed.
  InputError(std::string source, std::string key, std::string problem);

  const std::string& source() const noexcept { return source_; }
  const std::string& key() const noexcept { return key_; }
  const std::string& problem() const noexcept { return problem_; }

  // The same error, naming `source` if it named none.
  InputError with_source(const std::string& source) const;

 private:
  std::string source_;
  std::string key_;
  std::string problem_;
};

// Formats "source: key: problem", leaving out empty parts.
std::string format_input_error(const std::string& source, const std::string& key,
                               const std::string& problem);

}  // namespace rollnoise
