#pragma once
// Progress of long runs on a terminal: silent in CI (CI set), when stderr is not a terminal,
// and for runs that finish within about a second. Every update also polls the run's
// CancellationToken (core/cancellation.hpp): a loop that reports progress stops on Ctrl-C.
#include <chrono>
#include <cstddef>
#include <string>

#include "core/cancellation.hpp"

namespace rollnoise {

// Told how a run goes, for a caller that shows progress its own way (the Python module's
// callback). report() is called from the thread that runs the loop, at most about ten times a
// second per reporter and once when it finishes; it must be quick and must not throw.
class ProgressSink {
 public:
  virtual ~ProgressSink() = default;
  // `stage`: the reporter's label ("simulate case.toml", "radiation case.toml", ...); `done` of
  // `total` steps.
  virtual void report(const std::string& stage, std::size_t done, std::size_t total) noexcept = 0;
};

class ProgressReporter {
 public:
  // `cancel`: the token update() polls (by default the one SignalCancellation drives).
  // `shown` false: never drawn, but update() still polls `cancel`, so that a loop run quietly
  // (a study's cases, which draw one line of their own) still stops on Ctrl-C.
  // `sink` (optional, must outlive the reporter) is told of the progress whether or not it is
  // drawn.
  ProgressReporter(std::string label, std::size_t total, CancellationToken cancel = {}, bool shown = true,
                   ProgressSink* sink = nullptr);
  ~ProgressReporter();
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  // Cheap enough to call every step: it looks at the clock only every 256 calls. Throws
  // Interrupted when the token is cancelled (on every call: one relaxed atomic load).
  void update(std::size_t done);
  void finish();

  // True when progress would be shown at all (a terminal, not CI).
  static bool wanted();

 private:
  std::string label_;
  CancellationToken cancel_;
  ProgressSink* sink_;
  std::chrono::steady_clock::time_point last_sink_;
  std::size_t total_;
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace rollnoise
