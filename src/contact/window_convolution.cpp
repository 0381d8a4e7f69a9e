#include "contact/window_convolution.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <new>
#include <stdexcept>

#include "core/avx_support.hpp"
#include "core/real_fft_batch.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rollnoise {
namespace {

// Bins per row are padded to a multiple of the multiply-add loop's chunk.
constexpr int chunk = 8;

// The transforms' length: the smallest n ≥ 2W − 1 of the form 2^a·m, a ≥ 3, m ∈ {1, 3, 5, 7,
// 13}. FFTW_ESTIMATE (the only planning that gives the same plan, so the same bits, on every
// run) plans these well; with Debian 12's FFTW 3.3.10, 20 real transforms each way took 4.2 µs
// at 104 = 8·13 against 5.0 µs at 108 = 4·27 (the smallest 2^a·3^b·5^c), and 7.0 against 9.8 µs
// at 208 = 16·13 against 216 (the plate's 512- and 1024-cell windows, W = 52 and 103).
int convolution_length(int window) {
  const int least = std::max(2 * window - 1, 8);
  int best = 8;
  while (best < least) best *= 2;
  for (const int odd : {3, 5, 7, 13}) {
    int n = 8 * odd;
    while (n < least) n *= 2;
    best = std::min(best, n);
  }
  return best;
}

#if defined(ROLLNOISE_AVX_PATHS)
// multiply_block with four bins to a register, for processors with AVX (asked once, at
// construction): per lane the same multiplications and additions in the same order as the SSE2
// loop's, and no fused multiply-add, so both give the same bits. `kernel_*`: the block's kernel;
// `in_*`, `out_*`: its first row's spectra; rows `stride` bins apart.
__attribute__((target("avx"))) void multiply_block_avx(int size, int stride, const double* kernel_re,
                                                       const double* kernel_im, const double* in_re,
                                                       const double* in_im, double* out_re, double* out_im) {
  for (int a = 0; a < size; ++a) {
    double* yr = out_re + static_cast<std::size_t>(a) * stride;
    double* yi = out_im + static_cast<std::size_t>(a) * stride;
    for (int k0 = 0; k0 < stride; k0 += chunk) {
      __m256d sr[chunk / 4], si[chunk / 4];
      for (int c = 0; c < chunk / 4; ++c) sr[c] = si[c] = _mm256_setzero_pd();
      for (int b = 0; b < size; ++b) {
        const std::size_t slot = (static_cast<std::size_t>(a) * size + b) * stride + k0;
        const std::size_t row = static_cast<std::size_t>(b) * stride + k0;
        for (int c = 0; c < chunk / 4; ++c) {
          const __m256d vkr = _mm256_loadu_pd(kernel_re + slot + 4 * c), vki = _mm256_loadu_pd(kernel_im + slot + 4 * c);
          const __m256d vzr = _mm256_loadu_pd(in_re + row + 4 * c), vzi = _mm256_loadu_pd(in_im + row + 4 * c);
          sr[c] = _mm256_add_pd(sr[c], _mm256_sub_pd(_mm256_mul_pd(vkr, vzr), _mm256_mul_pd(vki, vzi)));
          si[c] = _mm256_add_pd(si[c], _mm256_add_pd(_mm256_mul_pd(vkr, vzi), _mm256_mul_pd(vki, vzr)));
        }
      }
      for (int c = 0; c < chunk / 4; ++c) {
        _mm256_storeu_pd(yr + k0 + 4 * c, sr[c]);
        _mm256_storeu_pd(yi + k0 + 4 * c, si[c]);
      }
    }
  }
}
#endif

#if defined(ROLLNOISE_AVX_PATHS)
// FFTW's interleaved bins split into real and imaginary rows, and back, four bins to two
// registers (the compiler's own loops move one value at a time): moves only, the same bits.
__attribute__((target("avx"))) void split_bins_avx(const double* from, int bins, double* to_re, double* to_im) {
  int k = 0;
  for (; k + 4 <= bins; k += 4) {
    const __m256d a = _mm256_loadu_pd(from + 2 * k), b = _mm256_loadu_pd(from + 2 * k + 4);  // r0 i0 r1 i1, r2 i2 r3 i3
    const __m256d even = _mm256_permute2f128_pd(a, b, 0x20), odd = _mm256_permute2f128_pd(a, b, 0x31);
    _mm256_storeu_pd(to_re + k, _mm256_unpacklo_pd(even, odd));
    _mm256_storeu_pd(to_im + k, _mm256_unpackhi_pd(even, odd));
  }
  for (; k < bins; ++k) {
    to_re[k] = from[2 * k];
    to_im[k] = from[2 * k + 1];
  }
}

__attribute__((target("avx"))) void join_bins_avx(const double* from_re, const double* from_im, int bins, double* to) {
  int k = 0;
  for (; k + 4 <= bins; k += 4) {
    const __m256d re = _mm256_loadu_pd(from_re + k), im = _mm256_loadu_pd(from_im + k);
    const __m256d even = _mm256_unpacklo_pd(re, im), odd = _mm256_unpackhi_pd(re, im);  // r0 i0 r2 i2, r1 i1 r3 i3
    _mm256_storeu_pd(to + 2 * k, _mm256_permute2f128_pd(even, odd, 0x20));
    _mm256_storeu_pd(to + 2 * k + 4, _mm256_permute2f128_pd(even, odd, 0x31));
  }
  for (; k < bins; ++k) {
    to[2 * k] = from_re[k];
    to[2 * k + 1] = from_im[k];
  }
}
#endif

// Whether G(i + W·j_p, W·j_q) and G(W·j_p, i + W·j_q) equal their mirror images across the
// centre line, G(i + W·(L−1−j_p), W·(L−1−j_q)) and so on, to round-off.
bool laterally_symmetric(const Eigen::MatrixXd& g, int window, int lateral) {
  const auto index = [window](int i, int j) { return i + Eigen::Index{window} * j; };
  const double limit = 1e-14 * g.cwiseAbs().maxCoeff();
  for (int jp = 0; jp < lateral; ++jp)
    for (int jq = 0; jq < lateral; ++jq)
      for (int d = 0; d < window; ++d) {
        const int mp = lateral - 1 - jp, mq = lateral - 1 - jq;
        if (std::abs(g(index(d, jp), index(0, jq)) - g(index(d, mp), index(0, mq))) > limit ||
            std::abs(g(index(0, jp), index(d, jq)) - g(index(0, mp), index(d, mq))) > limit)
          return false;
      }
  return true;
}

}  // namespace

WindowConvolution::WindowConvolution(const Eigen::MatrixXd& g, int window, int lateral)
    : window_(window),
      lateral_(lateral),
      length_(convolution_length(window)),
      bins_(length_ / 2 + 1),
      stride_((bins_ + chunk - 1) / chunk * chunk) {
  if (window < 1 || lateral < 1) throw std::invalid_argument("window convolution: empty window");
  const Eigen::Index points = Eigen::Index{window} * lateral;
  if (g.rows() != points || g.cols() != points) throw std::invalid_argument("window convolution: G must be (W·L) × (W·L)");
  const auto index = [window](int i, int j) { return i + Eigen::Index{window} * j; };
  // K̂(k, j_p, j_q)/N of each pair of rows (FFTW's c2r is unnormalised).
  std::vector<std::complex<double>> spectrum(static_cast<std::size_t>(lateral) * lateral * bins_);
  const auto at = [&](int jp, int jq, int k) -> std::complex<double>& {
    return spectrum[(static_cast<std::size_t>(jp) * lateral + jq) * bins_ + k];
  };
  RealFftBatch column(length_, 1);
  const auto lags = static_cast<std::size_t>(2 * window - 1);
  lags_.resize(static_cast<std::size_t>(lateral) * lateral * lags);
  for (int jp = 0; jp < lateral; ++jp)
    for (int jq = 0; jq < lateral; ++jq) {
      // c[d mod N] = g(d) for d = i_p − i_q from −(W − 1) to W − 1; zero between.
      for (int k = 0; k < length_; ++k) column.at(0, k) = 0.0;
      for (int d = 0; d < window; ++d) column.at(0, d) = g(index(d, jp), index(0, jq));
      for (int d = 1; d < window; ++d) column.at(0, length_ - d) = g(index(0, jp), index(d, jq));
      double* lag = lags_.data() + (static_cast<std::size_t>(jq) * lateral + jp) * lags + (window - 1);
      for (int d = 0; d < window; ++d) lag[d] = column.at(0, d);
      for (int d = 1; d < window; ++d) lag[-d] = column.at(0, length_ - d);
      column.forward();
      for (int k = 0; k < bins_; ++k) at(jp, jq, k) = column.bin(0, k) / static_cast<double>(length_);
    }
  // The blocks' kernels. Folded, with h = ⌊L/2⌋ pairs of rows (a, L−1−a) and for odd L the
  // middle row m: the even block maps e_b = z_b + z_{L−1−b} (b < h), e_m = z_m to
  // y_a + y_{L−1−a} and y_m, the odd block o_b = z_b − z_{L−1−b} to y_a − y_{L−1−a}.
  folded_ = lateral > 1 && laterally_symmetric(g, window, lateral);
  const int half = lateral / 2;
  even_ = folded_ ? (lateral + 1) / 2 : lateral;
  const int odd = lateral - even_;
  const auto block_entry = [&](bool even_block, int a, int b, int k) -> std::complex<double> {
    if (!folded_) return at(a, b, k);
    if (!even_block) return at(a, b, k) - at(a, lateral - 1 - b, k);
    if (a < half) return b < half ? at(a, b, k) + at(a, lateral - 1 - b, k) : 2.0 * at(a, b, k);
    return at(a, b, k);  // the middle row: G(m, L−1−b) = G(m, b)
  };
  const auto allocate = [](std::size_t count) {
    Buffer buffer(fftw_alloc_real(count));
    if (!buffer) throw std::bad_alloc();
    std::fill(buffer.get(), buffer.get() + count, 0.0);
    return buffer;
  };
  odd_kernel_ = static_cast<std::size_t>(even_) * even_ * stride_;
  const std::size_t kernel_size = odd_kernel_ + static_cast<std::size_t>(odd) * odd * stride_;
  kernel_re_ = allocate(kernel_size);
  kernel_im_ = allocate(kernel_size);
  for (const bool even_block : {true, false}) {
    const int size = even_block ? even_ : odd;
    const std::size_t start = even_block ? 0 : odd_kernel_;
    for (int a = 0; a < size; ++a)
      for (int b = 0; b < size; ++b)
        for (int k = 0; k < bins_; ++k) {
          const std::complex<double> value = block_entry(even_block, a, b, k);
          const std::size_t slot = start + (static_cast<std::size_t>(a) * size + b) * stride_ + k;
          kernel_re_.get()[slot] = value.real();
          kernel_im_.get()[slot] = value.imag();
        }
  }
  const std::size_t spectra = static_cast<std::size_t>(lateral) * stride_;
  field_ = allocate(static_cast<std::size_t>(lateral) * length_);
  in_re_ = allocate(spectra);
  in_im_ = allocate(spectra);
  out_re_ = allocate(spectra);
  out_im_ = allocate(spectra);
  spectrum_ = allocate(2 * static_cast<std::size_t>(lateral) * bins_);
  use_avx(true);
  // The L rows' transforms, interleaved (FFTW's split-array plans are about twice as slow),
  // planned without timing.
  forward_ = std::make_unique<FftwPlan>([this] {
    auto* bins = reinterpret_cast<fftw_complex*>(spectrum_.get());
    return fftw_plan_many_dft_r2c(1, &length_, lateral_, field_.get(), nullptr, 1, length_, bins, nullptr, 1, bins_,
                                  FFTW_ESTIMATE);
  });
  backward_ = std::make_unique<FftwPlan>([this] {
    auto* bins = reinterpret_cast<fftw_complex*>(spectrum_.get());
    return fftw_plan_many_dft_c2r(1, &length_, lateral_, bins, nullptr, 1, bins_, field_.get(), nullptr, 1, length_,
                                  FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  });
}

bool WindowConvolution::use_avx(bool on) noexcept {
  avx_ = avx_available(on);
  return avx_;
}

void WindowConvolution::multiply_block(int offset, int size, const double* kernel_re, const double* kernel_im) {
#if defined(ROLLNOISE_AVX_PATHS)
  if (avx_) {
    multiply_block_avx(size, stride_, kernel_re, kernel_im, re(in_re_.get(), offset), re(in_im_.get(), offset),
                       re(out_re_.get(), offset), re(out_im_.get(), offset));
    return;
  }
#endif
  // Per output row and chunk of 8 bins, the sum over input rows stays in registers (the
  // compiler's own vectorisation of this loop mixes packed and scalar adds: SSE2 by hand).
  for (int a = 0; a < size; ++a) {
    double* yr = re(out_re_.get(), offset + a);
    double* yi = re(out_im_.get(), offset + a);
    for (int k0 = 0; k0 < stride_; k0 += chunk) {
#if defined(__SSE2__)
      __m128d sr[chunk / 2], si[chunk / 2];
      for (int c = 0; c < chunk / 2; ++c) sr[c] = si[c] = _mm_setzero_pd();
      for (int b = 0; b < size; ++b) {
        const std::size_t slot = (static_cast<std::size_t>(a) * size + b) * stride_ + k0;
        const double* kr = kernel_re + slot;
        const double* ki = kernel_im + slot;
        const double* zr = re(in_re_.get(), offset + b) + k0;
        const double* zi = re(in_im_.get(), offset + b) + k0;
        for (int c = 0; c < chunk / 2; ++c) {
          const __m128d vkr = _mm_load_pd(kr + 2 * c), vki = _mm_load_pd(ki + 2 * c);
          const __m128d vzr = _mm_load_pd(zr + 2 * c), vzi = _mm_load_pd(zi + 2 * c);
          sr[c] = _mm_add_pd(sr[c], _mm_sub_pd(_mm_mul_pd(vkr, vzr), _mm_mul_pd(vki, vzi)));
          si[c] = _mm_add_pd(si[c], _mm_add_pd(_mm_mul_pd(vkr, vzi), _mm_mul_pd(vki, vzr)));
        }
      }
      for (int c = 0; c < chunk / 2; ++c) {
        _mm_store_pd(yr + k0 + 2 * c, sr[c]);
        _mm_store_pd(yi + k0 + 2 * c, si[c]);
      }
#else
      double sr[chunk] = {}, si[chunk] = {};
      for (int b = 0; b < size; ++b) {
        const std::size_t slot = (static_cast<std::size_t>(a) * size + b) * stride_ + k0;
        const double* kr = kernel_re + slot;
        const double* ki = kernel_im + slot;
        const double* zr = re(in_re_.get(), offset + b) + k0;
        const double* zi = re(in_im_.get(), offset + b) + k0;
        for (int k = 0; k < chunk; ++k) {
          sr[k] += kr[k] * zr[k] - ki[k] * zi[k];
          si[k] += kr[k] * zi[k] + ki[k] * zr[k];
        }
      }
      for (int k = 0; k < chunk; ++k) {
        yr[k0 + k] = sr[k];
        yi[k0 + k] = si[k];
      }
#endif
    }
  }
}

void WindowConvolution::subtract_column(Eigen::Index point, double factor, Eigen::VectorXd& y) const {
  const Eigen::Index points = Eigen::Index{window_} * lateral_;
  if (point < 0 || point >= points || y.size() != points) throw std::invalid_argument("window convolution: no such column");
  const auto iq = static_cast<int>(point % window_);
  const auto jq = static_cast<int>(point / window_);
  const auto lags = static_cast<std::size_t>(2 * window_ - 1);
  for (int jp = 0; jp < lateral_; ++jp) {
    // G(i_p + W·j_p, point) = lag i_p − i_q of the pair (j_p, j_q), for i_p = 0 … W − 1.
    const double* column = lags_.data() + (static_cast<std::size_t>(jq) * lateral_ + jp) * lags + (window_ - 1 - iq);
    double* out = y.data() + Eigen::Index{window_} * jp;
    for (int ip = 0; ip < window_; ++ip) out[ip] -= factor * column[ip];
  }
}

void WindowConvolution::apply(const Eigen::VectorXd& z, Eigen::VectorXd& y) {
  const Eigen::Index points = Eigen::Index{window_} * lateral_;
  if (z.size() != points) throw std::invalid_argument("window convolution: one value per point");
  if (y.size() != points) y.resize(points);
  double* field = field_.get();
  const auto row = [&](int j) { return field + static_cast<std::size_t>(j) * length_; };
  const auto zrow = [&](int j) { return z.data() + Eigen::Index{window_} * j; };
  const int half = lateral_ / 2;
  for (int j = 0; j < lateral_; ++j) std::fill(row(j) + window_, row(j) + length_, 0.0);
  if (folded_) {
    for (int a = 0; a < half; ++a) {
      const double* lo = zrow(a);
      const double* hi = zrow(lateral_ - 1 - a);
      double* even = row(a);
      double* odd = row(even_ + a);
      for (int i = 0; i < window_; ++i) {
        even[i] = lo[i] + hi[i];
        odd[i] = lo[i] - hi[i];
      }
    }
    if (lateral_ % 2) std::copy(zrow(half), zrow(half) + window_, row(half));
  } else {
    for (int j = 0; j < lateral_; ++j) std::copy(zrow(j), zrow(j) + window_, row(j));
  }
  forward_->execute();
  for (int j = 0; j < lateral_; ++j) {
    const double* from = spectrum_.get() + 2 * static_cast<std::size_t>(j) * bins_;
    double* to_re = re(in_re_.get(), j);
    double* to_im = re(in_im_.get(), j);
#if defined(ROLLNOISE_AVX_PATHS)
    if (avx_) {
      split_bins_avx(from, bins_, to_re, to_im);
      continue;
    }
#endif
    for (int k = 0; k < bins_; ++k) {
      to_re[k] = from[2 * k];
      to_im[k] = from[2 * k + 1];
    }
  }
  multiply_block(0, even_, kernel_re_.get(), kernel_im_.get());
  if (lateral_ > even_) multiply_block(even_, lateral_ - even_, kernel_re_.get() + odd_kernel_, kernel_im_.get() + odd_kernel_);
  for (int j = 0; j < lateral_; ++j) {
    const double* from_re = re(out_re_.get(), j);
    const double* from_im = re(out_im_.get(), j);
    double* to = spectrum_.get() + 2 * static_cast<std::size_t>(j) * bins_;
#if defined(ROLLNOISE_AVX_PATHS)
    if (avx_) {
      join_bins_avx(from_re, from_im, bins_, to);
      continue;
    }
#endif
    for (int k = 0; k < bins_; ++k) {
      to[2 * k] = from_re[k];
      to[2 * k + 1] = from_im[k];
    }
  }
  backward_->execute();
  double* out = y.data();
  if (folded_) {
    for (int a = 0; a < half; ++a) {
      const double* even = row(a);
      const double* odd = row(even_ + a);
      double* lo = out + Eigen::Index{window_} * a;
      double* hi = out + Eigen::Index{window_} * (lateral_ - 1 - a);
      for (int i = 0; i < window_; ++i) {
        lo[i] = 0.5 * (even[i] + odd[i]);
        hi[i] = 0.5 * (even[i] - odd[i]);
      }
    }
    if (lateral_ % 2) std::copy(row(half), row(half) + window_, out + Eigen::Index{window_} * half);
  } else {
    for (int j = 0; j < lateral_; ++j) std::copy(row(j), row(j) + window_, out + Eigen::Index{window_} * j);
  }
}

}  // namespace rollnoise
