#include "radiation/least_squares.hpp"

#include "core/blas_threads.hpp"

#include <cblas.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rollnoise {
namespace {

using Complex = std::complex<double>;

// LAPACK (Fortran interface; the hidden lengths of the character arguments last).
extern "C" {
void zpotrf_(const char* uplo, const int* n, Complex* a, const int* lda, int* info, std::size_t);
void zpotrs_(const char* uplo, const int* n, const int* nrhs, const Complex* a, const int* lda, Complex* b,
             const int* ldb, int* info, std::size_t);
void zpocon_(const char* uplo, const int* n, const Complex* a, const int* lda, const double* anorm, double* rcond,
             Complex* work, double* rwork, int* info, std::size_t);
double zlanhe_(const char* norm, const char* uplo, const int* n, const Complex* a, const int* lda, double* work,
               std::size_t, std::size_t);
void zgeqrf_(const int* m, const int* n, Complex* a, const int* lda, Complex* tau, Complex* work, const int* lwork,
             int* info);
void zunmqr_(const char* side, const char* trans, const int* m, const int* n, const int* k, const Complex* a,
             const int* lda, const Complex* tau, Complex* c, const int* ldc, Complex* work, const int* lwork, int* info,
             std::size_t, std::size_t);
void ztrtrs_(const char* uplo, const char* trans, const char* diag, const int* n, const int* nrhs, const Complex* a,
             const int* lda, Complex* b, const int* ldb, int* info, std::size_t, std::size_t, std::size_t);
}

// κ(AᴴA + λ²I) up to 1e11 keeps the normal equations: errors ≲ κε ≈ 1e-5 relative in q along
// the weakest directions, far less in what q radiates (measured on the tyre: transfers within
// 4e-5 of the QR's at κ ≈ 1e14).
constexpr double kSmallestReciprocalCondition = 1e-11;

int as_int(Eigen::Index n) {
  if (n < 0 || n > 0x7fffffff) throw std::length_error("least squares: matrix too large for the LAPACK interface");
  return static_cast<int>(n);
}

void check(int info, const char* routine) {
  if (info != 0) throw std::runtime_error(std::string("least squares: LAPACK ") + routine + " failed");
}

// Q (trans 'N') or Qᴴ ('C') of zgeqrf's reflectors applied to c from the left.
void apply_q(const Eigen::MatrixXcd& qr, const std::vector<Complex>& tau, const char* trans, Eigen::MatrixXcd& c) {
  const int m = as_int(c.rows()), n = as_int(c.cols()), k = as_int(qr.cols()), lda = as_int(qr.rows());
  if (n == 0) return;
  int info = 0, lwork = -1;
  Complex size;
  zunmqr_("L", trans, &m, &n, &k, qr.data(), &lda, tau.data(), c.data(), &m, &size, &lwork, &info, 1, 1);
  check(info, "zunmqr");
  lwork = static_cast<int>(size.real());
  std::vector<Complex> work(static_cast<std::size_t>(std::max(1, lwork)));
  zunmqr_("L", trans, &m, &n, &k, qr.data(), &lda, tau.data(), c.data(), &m, work.data(), &lwork, &info, 1, 1);
  check(info, "zunmqr");
}

}  // namespace

RegularisedLeastSquares::RegularisedLeastSquares(Eigen::MatrixXcd a, LeastSquaresMethod method)
    : a_(std::move(a)), method_(method) {
  if (a_.cols() < 1 || a_.rows() < 1) throw std::invalid_argument("least squares: need at least one row and one column");
  use_single_threaded_blas();
  const int m = as_int(a_.rows()), n = as_int(a_.cols());
  factor_.resize(n, n);
  cblas_zherk(CblasColMajor, CblasLower, CblasConjTrans, n, m, 1.0, a_.data(), m, 0.0, factor_.data(), n);
}

double RegularisedLeastSquares::largest_singular_value_squared(Eigen::VectorXcd x) const {
  if (factorised_) throw std::logic_error("least squares: the power iteration needs AᴴA, before factorise()");
  if (x.size() != a_.cols()) throw std::invalid_argument("least squares: one start value per column");
  const int n = as_int(a_.cols());
  const Complex one(1.0, 0.0), zero(0.0, 0.0);
  double value = 0.0;
  Eigen::VectorXcd y(n);
  for (int i = 0; i < 30; ++i) {
    cblas_zhemv(CblasColMajor, CblasLower, n, &one, factor_.data(), n, x.data(), 1, &zero, y.data(), 1);
    const double norm = y.norm();
    if (!(norm > 0.0)) break;
    value = norm / x.norm();
    x = y / norm;
  }
  return value;
}

void RegularisedLeastSquares::factorise(double lambda) {
  if (factorised_) throw std::logic_error("least squares: factorised twice");
  if (!(lambda >= 0.0) || !std::isfinite(lambda)) throw std::invalid_argument("least squares: λ must be ≥ 0");
  factorised_ = true;
  const int n = as_int(a_.cols());
  factor_.diagonal().array() += lambda * lambda;
  std::vector<double> rwork(static_cast<std::size_t>(n));
  const double norm = zlanhe_("1", "L", &n, factor_.data(), &n, rwork.data(), 1, 1);
  int info = 0;
  zpotrf_("L", &n, factor_.data(), &n, &info, 1);
  if (info == 0) {
    std::vector<Complex> work(2 * static_cast<std::size_t>(n));
    zpocon_("L", &n, factor_.data(), &n, &norm, &rcond_, work.data(), rwork.data(), &info, 1);
    check(info, "zpocon");
    if (method_ == LeastSquaresMethod::normal_equations) return;
    if (rcond_ >= kSmallestReciprocalCondition && method_ == LeastSquaresMethod::automatic) return;
  } else {
    rcond_ = 0.0;
  }
  // The Householder QR of [A; λI].
  normal_ = false;
  const int rows = as_int(a_.rows() + a_.cols());
  factor_.setZero(rows, n);
  factor_.topRows(a_.rows()) = a_;
  factor_.bottomRows(n).diagonal().setConstant(lambda);
  tau_.assign(static_cast<std::size_t>(n), Complex(0.0, 0.0));
  int lwork = -1;
  Complex size;
  zgeqrf_(&rows, &n, factor_.data(), &rows, tau_.data(), &size, &lwork, &info);
  check(info, "zgeqrf");
  lwork = static_cast<int>(size.real());
  std::vector<Complex> work(static_cast<std::size_t>(std::max(1, lwork)));
  zgeqrf_(&rows, &n, factor_.data(), &rows, tau_.data(), work.data(), &lwork, &info);
  check(info, "zgeqrf");
  a_.resize(0, n);  // not needed by the QR
}

// Normal equations: q = (AᴴA + λ²I)⁻¹ Aᴴb. QR: q = R⁻¹ (Qᴴ[b; 0]) restricted to the first n rows.
Eigen::MatrixXcd RegularisedLeastSquares::solve(const Eigen::MatrixXcd& b) const {
  if (!factorised_) throw std::logic_error("least squares: not factorised");
  const int n = as_int(factor_.cols()), k = as_int(b.cols());
  if (k == 0) return Eigen::MatrixXcd(n, 0);
  int info = 0;
  if (normal_) {
    if (b.rows() != a_.rows()) throw std::invalid_argument("least squares: one right-hand side row per row of A");
    const int m = as_int(a_.rows());
    const Complex one(1.0, 0.0), zero(0.0, 0.0);
    Eigen::MatrixXcd q(n, k);
    cblas_zgemm(CblasColMajor, CblasConjTrans, CblasNoTrans, n, k, m, &one, a_.data(), m, b.data(), m, &zero, q.data(), n);
    zpotrs_("L", &n, &k, factor_.data(), &n, q.data(), &n, &info, 1);
    check(info, "zpotrs");
    return q;
  }
  const Eigen::Index m = factor_.rows() - n;
  if (b.rows() != m) throw std::invalid_argument("least squares: one right-hand side row per row of A");
  Eigen::MatrixXcd padded = Eigen::MatrixXcd::Zero(factor_.rows(), k);
  padded.topRows(m) = b;
  apply_q(factor_, tau_, "C", padded);
  const int lda = as_int(factor_.rows());
  ztrtrs_("U", "N", "N", &n, &k, factor_.data(), &lda, padded.data(), &lda, &info, 1, 1, 1);
  check(info, "ztrtrs");
  return padded.topRows(n);
}

// Normal equations: X A⁺ = (A G⁻¹ Xᴴ)ᴴ, G = AᴴA + λ²I. QR: X A⁺ = (X R⁻¹) Q₁ᴴ with Q₁ the first m
// rows of Q: Q applied to (X R⁻¹)ᴴ = R⁻ᴴXᴴ padded with zeros, first m rows, adjoint.
Eigen::MatrixXcd RegularisedLeastSquares::apply_pseudo_inverse_right(const Eigen::MatrixXcd& x) const {
  if (!factorised_) throw std::logic_error("least squares: not factorised");
  const int n = as_int(factor_.cols()), k = as_int(x.rows());
  if (x.cols() != n) throw std::invalid_argument("least squares: one column per column of A");
  int info = 0;
  if (normal_) {
    const int m = as_int(a_.rows());
    Eigen::MatrixXcd z = x.adjoint();
    if (k == 0) return Eigen::MatrixXcd(0, m);
    zpotrs_("L", &n, &k, factor_.data(), &n, z.data(), &n, &info, 1);
    check(info, "zpotrs");
    const Complex one(1.0, 0.0), zero(0.0, 0.0);
    Eigen::MatrixXcd w(m, k);
    cblas_zgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, m, k, n, &one, a_.data(), m, z.data(), n, &zero, w.data(), m);
    return w.adjoint();
  }
  const Eigen::Index m = factor_.rows() - n;
  if (k == 0) return Eigen::MatrixXcd(0, m);
  Eigen::MatrixXcd padded = Eigen::MatrixXcd::Zero(factor_.rows(), k);
  padded.topRows(n) = x.adjoint();
  const int lda = as_int(factor_.rows());
  ztrtrs_("U", "C", "N", &n, &k, factor_.data(), &lda, padded.data(), &lda, &info, 1, 1, 1);
  check(info, "ztrtrs");
  apply_q(factor_, tau_, "N", padded);
  return padded.topRows(m).adjoint();
}

Eigen::MatrixXcd RegularisedLeastSquares::apply_pseudo_inverse_right(const Eigen::MatrixXcd& x,
                                                                     const std::vector<Eigen::Index>& keep) const {
  if (!factorised_) throw std::logic_error("least squares: not factorised");
  const int n = as_int(factor_.cols()), k = as_int(x.rows());
  if (x.cols() != n) throw std::invalid_argument("least squares: one column per column of A");
  const Eigen::Index m = normal_ ? a_.rows() : factor_.rows() - n;
  for (const Eigen::Index i : keep)
    if (i < 0 || i >= m) throw std::invalid_argument("least squares: a kept column out of range");
  const int kept = as_int(static_cast<Eigen::Index>(keep.size()));
  if (!normal_ || k == 0 || kept == 0) {
    const Eigen::MatrixXcd full = apply_pseudo_inverse_right(x);
    Eigen::MatrixXcd out(x.rows(), kept);
    for (int i = 0; i < kept; ++i) out.col(i) = full.col(keep[static_cast<std::size_t>(i)]);
    return out;
  }
  Eigen::MatrixXcd z = x.adjoint();
  int info = 0;
  zpotrs_("L", &n, &k, factor_.data(), &n, z.data(), &n, &info, 1);
  check(info, "zpotrs");
  Eigen::MatrixXcd rows(kept, n);
  for (int i = 0; i < kept; ++i) rows.row(i) = a_.row(keep[static_cast<std::size_t>(i)]);
  const Complex one(1.0, 0.0), zero(0.0, 0.0);
  Eigen::MatrixXcd w(kept, k);
  cblas_zgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, kept, k, n, &one, rows.data(), kept, z.data(), n, &zero, w.data(), kept);
  return w.adjoint();
}

Eigen::MatrixXcd blas_product(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b) {
  if (a.cols() != b.rows()) throw std::invalid_argument("blas_product: the inner dimensions differ");
  Eigen::MatrixXcd out(a.rows(), b.cols());
  if (out.size() == 0) return out;
  if (a.cols() == 0) return Eigen::MatrixXcd::Zero(a.rows(), b.cols());
  use_single_threaded_blas();
  const std::complex<double> one(1.0), zero(0.0);
  cblas_zgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, static_cast<int>(a.rows()), static_cast<int>(b.cols()),
              static_cast<int>(a.cols()), &one, a.data(), static_cast<int>(a.rows()), b.data(),
              static_cast<int>(b.rows()), &zero, out.data(), static_cast<int>(out.rows()));
  return out;
}

}  // namespace rollnoise
