#pragma once
// y = G·z for a contact matrix on the rolling tyre's window (W points along x by L rows, point
// p = i + W·j) that depends on i_p − i_q and the two rows only: a translation-invariant tyre,
// whose G0 is the same for every pair of points the same distance apart along x (checked by
// matrix_unchanged_by before use). Per pair of rows the product is a linear convolution of
// length 2W − 1 along x, done by FFT (FFTW, planned once) on a zero-padded length N ≥ 2W − 1:
// O(L·N log N + L²·N) operations on a kernel of L²·(N/2 + 1) complex values that stays in cache,
// instead of streaming the (W·L)² dense matrix. Nothing is allocated per product.
//
// The L²·(N/2 + 1) complex multiply-adds are most of a product's cost, so they are done on
// split real and imaginary arrays (they vectorise, where interleaved std::complex does not), and
// for a tyre symmetric about its centre line (G(j_p, j_q) = G(L−1−j_p, L−1−j_q) along x, checked
// to round-off) on the rows' even and odd combinations z_j ± z_{L−1−j}, which do not couple:
// two blocks of about L/2 rows, half the multiply-adds (the classical even/odd reduction of a
// centrosymmetric matrix, Cantoni & Butler, Linear Algebra Appl. 13 (1976) 275–288).
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "core/fftw_plan.hpp"

namespace rollnoise {

// The shape of a contact window whose matrix depends on x_p − x_q only (point p = i + W·j).
struct ContactWindow {
  int window = 0;   // points along x
  int lateral = 0;  // rows across
};

class WindowConvolution {
 public:
  // `g`: (W·L) × (W·L), read along its first row and column of each pair of rows.
  WindowConvolution(const Eigen::MatrixXd& g, int window, int lateral);

  // y = G·z (z, y of W·L values; may not alias).
  void apply(const Eigen::VectorXd& z, Eigen::VectorXd& y);
  // y −= factor·G(:, point): one column, from the kernel along x (L²·(2W − 1) values, which stay
  // in cache where the dense G does not: 8.6 MB on the plate's 1040 points).
  void subtract_column(Eigen::Index point, double factor, Eigen::VectorXd& y) const;

  int window() const noexcept { return window_; }
  int lateral() const noexcept { return lateral_; }
  // Whether the even/odd reduction of a laterally symmetric G is used.
  bool lateral_symmetry() const noexcept { return folded_; }
  // Whether the spectra's multiply-adds take four bins at a time (AVX, where the processor has
  // it: the default) or two (SSE2), and their splits into real and imaginary rows four bins at a
  // time or one; both give the same bits. Returns whether AVX is now used.
  bool use_avx(bool on) noexcept;

 private:
  struct FftwFree {
    void operator()(void* p) const noexcept { fftw_free(p); }
  };
  using Buffer = std::unique_ptr<double, FftwFree>;
  // Spectra of `rows` rows, b bins each (padded to `stride_`), real and imaginary apart.
  double* re(double* spectrum, int row) const noexcept { return spectrum + static_cast<std::size_t>(row) * stride_; }
  void multiply_block(int offset, int size, const double* kernel_re, const double* kernel_im);

  int window_, lateral_, length_, bins_, stride_;
  bool folded_ = false;  // rows as even/odd combinations
  bool avx_ = false;     // the multiply-adds four bins at a time (same bits as two at a time)
  int even_ = 0;         // rows in the even block (the odd block follows: lateral_ − even_)
  Buffer field_, spectrum_;                    // L rows of N values / of N/2 + 1 interleaved bins
  Buffer in_re_, in_im_, out_re_, out_im_;     // the spectra split, `stride_` bins a row
  Buffer kernel_re_, kernel_im_;               // per block, row-major (j_p, j_q), `stride_` bins each, divided by N
  std::vector<double> lags_;                   // G(i_p − i_q = d, j_p, j_q) at (j_q·L + j_p)·(2W − 1) + d + W − 1
  std::size_t odd_kernel_ = 0;                 // where the odd block's kernel starts
  std::unique_ptr<FftwPlan> forward_, backward_;
};

}  // namespace rollnoise
