#pragma once
// An FFTW plan owned RAII-style: made and destroyed under the one planner lock
// (fftw_planner_lock.hpp), executed without it. FFTW_ESTIMATE plans are chosen without timing,
// so results do not vary from run to run.
#include <fftw3.h>

#include <cstddef>
#include <stdexcept>

#include "core/fftw_planner_lock.hpp"

namespace rollnoise {

class FftwPlan {
 public:
  // `make` returns the new plan (called under the planner lock).
  template <class Make>
  explicit FftwPlan(Make make) {
    const std::lock_guard lock(fftw_planner_mutex());
    plan_ = make();
    if (!plan_) throw std::runtime_error("FFTW could not make a plan");
  }
  ~FftwPlan() {
    const std::lock_guard lock(fftw_planner_mutex());
    fftw_destroy_plan(plan_);
  }
  FftwPlan(const FftwPlan&) = delete;
  FftwPlan& operator=(const FftwPlan&) = delete;

  void execute() const { fftw_execute(plan_); }

 private:
  fftw_plan plan_ = nullptr;
};

// Smallest n' >= n of the form 2^a·3^b·5^c: sizes for which FFTW is fast.
inline std::size_t fft_friendly_size(std::size_t n) {
  std::size_t best = 1;
  while (best < n) best *= 2;  // a power of two always qualifies
  for (std::size_t p5 = 1; p5 < 2 * n; p5 *= 5) {
    for (std::size_t p35 = p5; p35 < 2 * n; p35 *= 3) {
      std::size_t candidate = p35;
      while (candidate < n) candidate *= 2;
      if (candidate < best) best = candidate;
    }
  }
  return best;
}

}  // namespace rollnoise
