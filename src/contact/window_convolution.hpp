#pragma once
// y = G·z for a contact matrix on the rolling tyre's window (W points along x by L rows, point
// p = i + W·j) that depends on i_p − i_q and the two rows only: a translation-invariant tyre,
// whose G0 is the same for every pair of points the same distance apart along x (checked by
// matrix_unchanged_by before use). Per pair of rows the product is a linear convolution of
// length 2W − 1 along x, done by FFT (FFTW, planned once) on a zero-padded length N ≥ 2W − 1:
// O(L·N log N + L²·N) operations on a kernel of L²·(N/2 + 1) complex values that stays in cache,
// instead of streaming the (W·L)² dense matrix. Nothing is allocated per product.
#include <complex>
#include <vector>

#include <Eigen/Core>

#include "core/real_fft_batch.hpp"

namespace rollnoise {

class WindowConvolution {
 public:
  // `g`: (W·L) × (W·L), read along its first row and column of each pair of rows.
  WindowConvolution(const Eigen::MatrixXd& g, int window, int lateral);

  // y = G·z (z, y of W·L values; may not alias).
  void apply(const Eigen::VectorXd& z, Eigen::VectorXd& y);

  int window() const noexcept { return window_; }
  int lateral() const noexcept { return lateral_; }

 private:
  int window_, lateral_, length_;
  RealFftBatch in_, out_;
  // K̂(k, j_p, j_q) at kernel_[(j_p·L + j_q)·(N/2 + 1) + k], divided by N (FFTW's c2r is unnormalised).
  std::vector<std::complex<double>> kernel_;
};

}  // namespace rollnoise
