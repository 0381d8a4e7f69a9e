#include "contact/window_convolution.hpp"

#include <stdexcept>

#include "core/fftw_plan.hpp"

namespace rollnoise {

WindowConvolution::WindowConvolution(const Eigen::MatrixXd& g, int window, int lateral)
    : window_(window),
      lateral_(lateral),
      length_(static_cast<int>(fft_friendly_size(static_cast<std::size_t>(2 * window - 1)))),
      in_(length_, lateral),
      out_(length_, lateral) {
  if (window < 1 || lateral < 1) throw std::invalid_argument("window convolution: empty window");
  const Eigen::Index points = Eigen::Index{window} * lateral;
  if (g.rows() != points || g.cols() != points) throw std::invalid_argument("window convolution: G must be (W·L) × (W·L)");
  const auto index = [window](int i, int j) { return i + Eigen::Index{window} * j; };
  const int bins = in_.bins();
  kernel_.resize(static_cast<std::size_t>(lateral) * lateral * bins);
  RealFftBatch column(length_, 1);
  for (int jp = 0; jp < lateral; ++jp)
    for (int jq = 0; jq < lateral; ++jq) {
      // c[d mod N] = g(d) for d = i_p − i_q from −(W − 1) to W − 1; zero between.
      for (int k = 0; k < length_; ++k) column.at(0, k) = 0.0;
      for (int d = 0; d < window; ++d) column.at(0, d) = g(index(d, jp), index(0, jq));
      for (int d = 1; d < window; ++d) column.at(0, length_ - d) = g(index(0, jp), index(d, jq));
      column.forward();
      for (int k = 0; k < bins; ++k)
        kernel_[(static_cast<std::size_t>(jp) * lateral + jq) * bins + k] = column.bin(0, k) / static_cast<double>(length_);
    }
}

void WindowConvolution::apply(const Eigen::VectorXd& z, Eigen::VectorXd& y) {
  const Eigen::Index points = Eigen::Index{window_} * lateral_;
  if (z.size() != points) throw std::invalid_argument("window convolution: one value per point");
  if (y.size() != points) y.resize(points);
  for (int j = 0; j < lateral_; ++j) {
    for (int i = 0; i < window_; ++i) in_.at(j, i) = z(i + Eigen::Index{window_} * j);
    for (int i = window_; i < length_; ++i) in_.at(j, i) = 0.0;
  }
  in_.forward();
  const int bins = in_.bins();
  // Complex products written out in reals: std::complex's operator* checks for infinities
  // (__muldc3) and does not vectorise.
  for (int jp = 0; jp < lateral_; ++jp) {
    double* out = reinterpret_cast<double*>(&out_.bin(jp, 0));
    for (int k = 0; k < 2 * bins; ++k) out[k] = 0.0;
    for (int jq = 0; jq < lateral_; ++jq) {
      const double* kernel = reinterpret_cast<const double*>(&kernel_[(static_cast<std::size_t>(jp) * lateral_ + jq) * bins]);
      const double* in = reinterpret_cast<const double*>(&in_.bin(jq, 0));
      for (int k = 0; k < bins; ++k) {
        const double kr = kernel[2 * k], ki = kernel[2 * k + 1], zr = in[2 * k], zi = in[2 * k + 1];
        out[2 * k] += kr * zr - ki * zi;
        out[2 * k + 1] += kr * zi + ki * zr;
      }
    }
  }
  out_.backward();
  for (int j = 0; j < lateral_; ++j)
    for (int i = 0; i < window_; ++i) y(i + Eigen::Index{window_} * j) = out_.at(j, i);
}

}  // namespace rollnoise
