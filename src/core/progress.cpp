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

ProgressReporter::ProgressReporter(std::string label, std::size_t total, CancellationToken cancel, bool shown)
    : label_(std::move(label)),
      cancel_(cancel),
      total_(total),
      enabled_(shown && wanted()),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

ProgressReporter::~ProgressReporter() { finish(); }

void ProgressReporter::update(std::size_t done) {
  cancel_.throw_if_cancelled();
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
  if (shown_) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr, "\r%s: done in %.1f s%30s\n", label_.c_str(), elapsed, "");
    shown_ = false;
  }
  enabled_ = false;
}

}  // namespace rollnoise
