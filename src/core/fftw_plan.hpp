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

// Smallest n' >= n of the form 2^a·3^b·5^c: sizes for which FFTW is fast. (The road generators'
// lengths; kept to these factors so that a seeded road stays the same road.)
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

// Whether FFTW transforms length n with its fast codelets alone: n = 2^a·3^b·5^c·7^d·11^e·13^f
// with e + f ≤ 1 (FFTW's manual, "Complex One-Dimensional DFTs"). Other lengths fall to Rader's
// or generic algorithms, several times slower, which allocate scratch on every execution.
// Measured with FFTW_ESTIMATE on 25 real inverse transforms (the belt's lateral shapes): 1016 =
// 8·127 takes 3.9× the time of 1024, and 1626 = 2·3·271 takes 3.1× that of 1638 = 2·3²·7·13.
constexpr bool fftw_fast_length(long n) {
  if (n < 1) return false;
  for (const long p : {2L, 3L, 5L, 7L}) {
    while (n % p == 0) n /= p;
  }
  return n == 1 || n == 11 || n == 13;
}

// The least n' ≥ n with fftw_fast_length(n'), even when `even` (a real transform's Nyquist bin).
// Such lengths lie within a few per cent of each other, so the search is short.
constexpr long next_fftw_fast_length(long n, bool even) {
  if (n < 1) throw std::invalid_argument("next_fftw_fast_length: n must be >= 1");
  for (long m = n;; ++m) {
    if (even && m % 2 != 0) continue;
    if (fftw_fast_length(m)) return m;
  }
}

}  // namespace rollnoise
