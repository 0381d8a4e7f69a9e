#include "contact/pole_recursion.hpp"

#include <stdexcept>
#include <utility>

#include "core/avx_support.hpp"

namespace rollnoise {
namespace {

// The pass's arrays as interleaved reals (std::complex<double> is laid out as two doubles,
// [complex.numbers.general]): pole s at 2s (real) and 2s + 1 (imaginary).
struct PolePass {
  std::size_t modes;
  const std::size_t* first;
  const double *a, *b;
  double* y;
  const double* force;  // per mode, interleaved likewise
  double* coming;       // per mode, or null
};

template <bool Predict>
void advance_scalar(const PolePass& c) {
  for (std::size_t r = 0; r < c.modes; ++r) {
    const double fr = c.force[2 * r], fi = c.force[2 * r + 1];
    double sum_re = 0.0, sum_im = 0.0;
    for (std::size_t s = c.first[r]; s < c.first[r + 1]; ++s) {
      const double ar = c.a[2 * s], ai = c.a[2 * s + 1], br = c.b[2 * s], bi = c.b[2 * s + 1];
      const double yr = c.y[2 * s], yi = c.y[2 * s + 1];
      const double pr = ar * yr - ai * yi, pi = ar * yi + ai * yr;
      const double nr = pr + br * fr - bi * fi, ni = pi + br * fi + bi * fr;
      c.y[2 * s] = nr;
      c.y[2 * s + 1] = ni;
      if constexpr (Predict) {
        sum_re += ar * nr - ai * ni;
        sum_im += ar * ni + ai * nr;
      }
    }
    if constexpr (Predict) {
      c.coming[2 * r] = sum_re;
      c.coming[2 * r + 1] = sum_im;
    }
  }
}

#if defined(ROLLNOISE_AVX_PATHS)
// a·y for two interleaved complex values: [a_r y_r − a_i y_i, a_r y_i + a_i y_r] per pole
// (addsub subtracts in the even lanes and adds in the odd ones).
__attribute__((target("avx"))) inline __m256d multiply2(__m256d a, __m256d y) {
  const __m256d a_re = _mm256_movedup_pd(a), a_im = _mm256_permute_pd(a, 0xF), y_swapped = _mm256_permute_pd(y, 0x5);
  return _mm256_addsub_pd(_mm256_mul_pd(a_re, y), _mm256_mul_pd(a_im, y_swapped));
}

__attribute__((target("avx"))) inline __m128d multiply1(__m128d a, __m128d y) {
  const __m128d a_re = _mm_movedup_pd(a), a_im = _mm_permute_pd(a, 0x3), y_swapped = _mm_permute_pd(y, 0x1);
  return _mm_addsub_pd(_mm_mul_pd(a_re, y), _mm_mul_pd(a_im, y_swapped));
}

// advance_scalar two poles to a register: the same operations per value in the same order, and
// each mode's sum taken pole by pole (the low half, then the high half), so the same bits.
template <bool Predict>
__attribute__((target("avx"))) void advance_avx(const PolePass& c) {
  const double *a = c.a, *b = c.b;
  double* y = c.y;
  for (std::size_t r = 0; r < c.modes; ++r) {
    const double fr = c.force[2 * r], fi = c.force[2 * r + 1];
    const __m256d f = _mm256_setr_pd(fr, fi, fr, fi), f_swapped = _mm256_setr_pd(fi, fr, fi, fr);
    __m128d sum = _mm_setzero_pd();
    std::size_t s = c.first[r];
    const std::size_t end = c.first[r + 1];
    for (; s + 2 <= end; s += 2) {
      const __m256d av = _mm256_loadu_pd(a + 2 * s), bv = _mm256_loadu_pd(b + 2 * s);
      const __m256d predicted = multiply2(av, _mm256_loadu_pd(y + 2 * s));
      // (a·y)_r + b_r f_r − b_i f_i and (a·y)_i + b_r f_i + b_i f_r.
      const __m256d with_real = _mm256_add_pd(predicted, _mm256_mul_pd(_mm256_movedup_pd(bv), f));
      const __m256d next = _mm256_addsub_pd(with_real, _mm256_mul_pd(_mm256_permute_pd(bv, 0xF), f_swapped));
      _mm256_storeu_pd(y + 2 * s, next);
      if constexpr (Predict) {
        const __m256d coming = multiply2(av, next);
        sum = _mm_add_pd(sum, _mm256_castpd256_pd128(coming));
        sum = _mm_add_pd(sum, _mm256_extractf128_pd(coming, 1));
      }
    }
    if (s < end) {
      const __m128d av = _mm_loadu_pd(a + 2 * s), bv = _mm_loadu_pd(b + 2 * s);
      const __m128d predicted = multiply1(av, _mm_loadu_pd(y + 2 * s));
      const __m128d with_real = _mm_add_pd(predicted, _mm_mul_pd(_mm_movedup_pd(bv), _mm256_castpd256_pd128(f)));
      const __m128d next =
          _mm_addsub_pd(with_real, _mm_mul_pd(_mm_permute_pd(bv, 0x3), _mm256_castpd256_pd128(f_swapped)));
      _mm_storeu_pd(y + 2 * s, next);
      if constexpr (Predict) sum = _mm_add_pd(sum, multiply1(av, next));
    }
    if constexpr (Predict) _mm_storeu_pd(c.coming + 2 * r, sum);
  }
}
#endif

}  // namespace

PoleRecursion::PoleRecursion(std::vector<std::size_t> first_pole, std::vector<std::complex<double>> decay,
                             std::vector<std::complex<double>> input)
    : first_pole_(std::move(first_pole)), decay_(std::move(decay)), input_(std::move(input)) {
  if (first_pole_.empty() || first_pole_.front() != 0 || first_pole_.back() != decay_.size() ||
      input_.size() != decay_.size())
    throw std::invalid_argument("pole recursion: one decay and one input per pole, poles numbered from 0 by mode");
  for (std::size_t r = 0; r + 1 < first_pole_.size(); ++r)
    if (first_pole_[r + 1] < first_pole_[r]) throw std::invalid_argument("pole recursion: modes out of order");
  states_.assign(decay_.size(), 0.0);
  use_avx(true);
}

bool PoleRecursion::use_avx(bool on) noexcept {
  avx_ = avx_available(on);
  return avx_;
}

void PoleRecursion::advance(const std::complex<double>* force, std::complex<double>* coming) {
  const PolePass pass{modes(),
                      first_pole_.data(),
                      reinterpret_cast<const double*>(decay_.data()),
                      reinterpret_cast<const double*>(input_.data()),
                      reinterpret_cast<double*>(states_.data()),
                      reinterpret_cast<const double*>(force),
                      reinterpret_cast<double*>(coming)};
#if defined(ROLLNOISE_AVX_PATHS)
  if (avx_) {
    if (coming) advance_avx<true>(pass);
    else advance_avx<false>(pass);
    return;
  }
#endif
  if (coming) advance_scalar<true>(pass);
  else advance_scalar<false>(pass);
}

void PoleRecursion::predict(std::complex<double>* coming) const {
  for (std::size_t r = 0; r < modes(); ++r) {
    double sum_re = 0.0, sum_im = 0.0;
    for (std::size_t s = first_pole_[r]; s < first_pole_[r + 1]; ++s) {
      const double ar = decay_[s].real(), ai = decay_[s].imag(), yr = states_[s].real(), yi = states_[s].imag();
      sum_re += ar * yr - ai * yi;
      sum_im += ar * yi + ai * yr;
    }
    coming[r] = {sum_re, sum_im};
  }
}

}  // namespace rollnoise
