#include "core/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace rollnoise {

bool ProgressReporter::wanted() {
  const char* ci = std::getenv("CI");
  const bool in_ci = ci != nullptr && *ci != '\0' && std::string(ci) != "false";
  return !in_ci && ::isatty(STDERR_FILENO) == 1;
}

ProgressReporter::ProgressReporter(std::string label, std::size_t total, CancellationToken cancel, bool shown,
                                   ProgressSink* sink)
    : label_(std::move(label)),
      cancel_(cancel),
      sink_(sink),
      total_(total),
      enabled_(shown && wanted()),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {
  last_sink_ = start_;
  if (sink_) sink_->report(label_, 0, total_);
}

ProgressReporter::~ProgressReporter() {
  sink_ = nullptr;  // a run cut off by an error has not finished
  finish();
}

void ProgressReporter::update(std::size_t done) {
  cancel_.throw_if_cancelled();
  if (sink_) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_sink_ >= std::chrono::milliseconds(100)) {
      last_sink_ = now;
      sink_->report(label_, done, total_);
    }
  }
  if (!enabled_ || (done & 255u) != 0) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 1.0 || now - last_ < std::chrono::milliseconds(200)) return;
  last_ = now;
  shown_ = true;
  const double fraction = total_ ? static_cast<double>(done) / static_cast<double>(total_) : 0.0;
  const double remaining = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "\r%s: %5.1f%%  %.0f s elapsed, about %.0f s left   ", label_.c_str(),
               100.0 * fraction, elapsed, remaining);
  std::fflush(stderr);
}

void ProgressReporter::finish() {
  if (sink_) {
    sink_->report(label_, total_, total_);
    sink_ = nullptr;
  }
  if (shown_) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr, "\r%s: done in %.1f s%30s\n", label_.c_str(), elapsed, "");
    shown_ = false;
  }
  enabled_ = false;
}

}  // namespace rollnoise
