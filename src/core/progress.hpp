#pragma once
// Progress of long runs on a terminal: silent in CI (CI set), when stderr is not a terminal,
// and for runs that finish within about a second.
#include <chrono>
#include <cstddef>
#include <string>

namespace rollnoise {

class ProgressReporter {
 public:
  ProgressReporter(std::string label, std::size_t total);
  ~ProgressReporter();
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  // Cheap enough to call every step: it looks at the clock only every 256 calls.
  void update(std::size_t done);
  void finish();

  // True when progress would be shown at all (a terminal, not CI).
  static bool wanted();

 private:
  std::string label_;
  std::size_t total_;
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace rollnoise
