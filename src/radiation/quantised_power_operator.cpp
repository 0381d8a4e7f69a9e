#include "radiation/quantised_power_operator.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include <cblas.h>

#include "core/blas_threads.hpp"
#include "radiation/least_squares.hpp"

namespace rollnoise {
namespace {

using Complex = std::complex<double>;

// LAPACK (Fortran interface; the hidden lengths of the character arguments last).
extern "C" void zheevd_(const char* jobz, const char* uplo, const int* n, Complex* a, const int* lda, double* w,
                        Complex* work, const int* lwork, double* rwork, const int* lrwork, int* iwork,
                        const int* liwork, int* info, std::size_t, std::size_t);

constexpr double kLargestInteger = 32767.0;

// The eigenvectors of the Hermitian `a` (overwritten), by decreasing eigenvalue.
Eigen::MatrixXcd eigenvectors_decreasing(Eigen::MatrixXcd a) {
  const Eigen::Index n = a.rows();
  if (n > 0x7fffffff) throw std::length_error("power operator: block too large for the LAPACK interface");
  const int size = static_cast<int>(n);
  std::vector<double> values(static_cast<std::size_t>(n));
  int info = 0, query = -1;
  Complex work_size;
  double rwork_size = 0.0;
  int iwork_size = 0;
  use_single_threaded_blas();
  zheevd_("V", "L", &size, a.data(), &size, values.data(), &work_size, &query, &rwork_size, &query, &iwork_size,
          &query, &info, 1, 1);
  if (info != 0) throw std::runtime_error("power operator: LAPACK zheevd failed (workspace query)");
  // zheevd's own query asks for 2n + n² (its minimum) and leaves the back-transformation of the
  // eigenvectors (zunmtr) the workspace's rest, nothing: it then ran unblocked (zunm2r, 4 % of a
  // cold anchor on the split mesh). n·64 + 65·64 more lets zunmqr take its blocks of 64 (LAPACK's
  // NBMAX and its T factor's size).
  const long blocked = 2L * n + n * n + 64L * n + 65L * 64L;
  if (blocked > 0x7fffffff) throw std::length_error("power operator: block too large for the LAPACK interface");
  const int lwork = std::max({1, static_cast<int>(work_size.real()), static_cast<int>(blocked)});
  const int lrwork = std::max(1, static_cast<int>(rwork_size));
  const int liwork = std::max(1, iwork_size);
  std::vector<Complex> work(static_cast<std::size_t>(lwork));
  std::vector<double> rwork(static_cast<std::size_t>(lrwork));
  std::vector<int> iwork(static_cast<std::size_t>(liwork));
  zheevd_("V", "L", &size, a.data(), &size, values.data(), work.data(), &lwork, rwork.data(), &lrwork, iwork.data(),
          &liwork, &info, 1, 1);
  if (info != 0) throw std::runtime_error("power operator: LAPACK zheevd failed (info " + std::to_string(info) + ")");
  return a.rowwise().reverse();  // zheevd orders the eigenvalues increasing
}

// The largest row norm: σ₁ of the block (its rows are the singular values times orthonormal
// rows), and a bound on every real and imaginary part in it.
double largest_row(const Eigen::MatrixXcd& m) {
  if (m.size() == 0) return 0.0;
  return m.rowwise().norm().maxCoeff();
}

}  // namespace

QuantisedPower quantise_power_operator(const std::vector<Eigen::MatrixXcd>& blocks) {
  std::vector<Eigen::MatrixXcd> rotated;
  rotated.reserve(blocks.size());
  double largest = 0.0;
  for (const Eigen::MatrixXcd& q : blocks) {
    if (q.rows() == 0 || q.cols() == 0) {
      rotated.emplace_back(0, q.cols());
      continue;
    }
    // QQᴴ by zherk (its lower triangle, all zheevd reads): half the flops of the full product.
    Eigen::MatrixXcd gram(q.rows(), q.rows());
    if (q.rows() > 0x7fffffff || q.cols() > 0x7fffffff)
      throw std::length_error("power operator: block too large for the BLAS interface");
    use_single_threaded_blas();
    cblas_zherk(CblasColMajor, CblasLower, CblasNoTrans, static_cast<int>(q.rows()), static_cast<int>(q.cols()), 1.0, q.data(),
                static_cast<int>(q.rows()), 0.0, gram.data(), static_cast<int>(q.rows()));
    const Eigen::MatrixXcd u = eigenvectors_decreasing(std::move(gram));
    rotated.push_back(blas_product(u.adjoint(), q));
    largest = std::max(largest, largest_row(rotated.back()));
  }
  QuantisedPower out;
  if (!(largest > 0.0) || !std::isfinite(largest)) {
    for (const Eigen::MatrixXcd& q : blocks) out.blocks.emplace_back(0, q.cols());
    return out;
  }
  out.quantum = largest / kLargestInteger;
  for (const Eigen::MatrixXcd& b : rotated) {
    Eigen::MatrixXcd rounded(b.rows(), b.cols());
    for (Eigen::Index j = 0; j < b.cols(); ++j)
      for (Eigen::Index i = 0; i < b.rows(); ++i)
        rounded(i, j) = Complex(std::nearbyint(b(i, j).real() / out.quantum) * out.quantum,
                                std::nearbyint(b(i, j).imag() / out.quantum) * out.quantum);
    // Rows that round to zero carry nothing: dropped (a weak block may lose them all).
    std::vector<Eigen::Index> kept;
    for (Eigen::Index i = 0; i < rounded.rows(); ++i)
      if (rounded.row(i).cwiseAbs2().maxCoeff() > 0.0) kept.push_back(i);
    Eigen::MatrixXcd block(static_cast<Eigen::Index>(kept.size()), b.cols());
    for (std::size_t i = 0; i < kept.size(); ++i) block.row(static_cast<Eigen::Index>(i)) = rounded.row(kept[i]);
    out.blocks.push_back(std::move(block));
  }
  return out;
}

Int16Matrix integers_of(const Eigen::MatrixXd& part, double quantum) {
  Int16Matrix out(part.rows(), part.cols());
  if (part.size() == 0) return out;
  if (!(quantum > 0.0) || !std::isfinite(quantum))
    throw std::invalid_argument("power operator: the quantum must be positive and finite");
  for (Eigen::Index i = 0; i < part.rows(); ++i)
    for (Eigen::Index j = 0; j < part.cols(); ++j) {
      const double scaled = part(i, j) / quantum;
      const double integer = std::nearbyint(scaled);
      if (!(std::abs(integer) <= kLargestInteger) || std::abs(scaled - integer) > 1e-6)
        throw std::invalid_argument("power operator: a value is not a 16-bit multiple of the quantum");
      out(i, j) = static_cast<std::int16_t>(integer);
    }
  return out;
}

Eigen::MatrixXd values_of(const Int16Matrix& integers, double quantum) {
  return integers.cast<double>() * quantum;
}

}  // namespace rollnoise
