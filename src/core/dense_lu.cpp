#include "core/dense_lu.hpp"

#include <stdexcept>
#include <string>

#include "core/blas_threads.hpp"

namespace rollnoise {
namespace {

// LAPACK (Fortran interface; the hidden length of the character argument last).
extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda, const int* ipiv,
             double* b, const int* ldb, int* info, std::size_t);
}

int as_int(Eigen::Index n) {
  if (n < 0 || n > 0x7fffffff) throw std::length_error("dense LU: size too large for the LAPACK interface");
  return static_cast<int>(n);
}

}  // namespace

DenseLu::DenseLu(Eigen::Index capacity) : lu_(capacity, capacity), pivots_(static_cast<std::size_t>(capacity)) {
  as_int(capacity);
  use_single_threaded_blas();
}

void DenseLu::factorise(Eigen::Index n) {
  if (n < 0 || n > capacity()) throw std::invalid_argument("dense LU: size beyond the capacity");
  n_ = n;
  if (n == 0) return;
  const int size = as_int(n), lda = as_int(lu_.rows());
  int info = 0;
  dgetrf_(&size, &size, lu_.data(), &lda, pivots_.data(), &info);
  if (info < 0) throw std::invalid_argument("dense LU: dgetrf rejected argument " + std::to_string(-info));
  if (info > 0) throw std::domain_error("dense LU: the matrix is singular (zero pivot " + std::to_string(info) + ")");
}

void DenseLu::solve_in_place(Eigen::MatrixXd& b, Eigen::Index first_column, Eigen::Index columns) const {
  if (n_ == 0 || columns == 0) return;
  if (b.rows() < n_ || first_column < 0 || first_column + columns > b.cols())
    throw std::invalid_argument("dense LU: right-hand sides out of range");
  const int size = as_int(n_), nrhs = as_int(columns), lda = as_int(lu_.rows()), ldb = as_int(b.rows());
  int info = 0;
  dgetrs_("N", &size, &nrhs, lu_.data(), &lda, pivots_.data(), b.col(first_column).data(), &ldb, &info, 1);
  if (info != 0) throw std::invalid_argument("dense LU: dgetrs rejected argument " + std::to_string(-info));
}

void DenseLu::solve_in_place(Eigen::VectorXd& b) const {
  if (n_ == 0) return;
  if (b.size() < n_) throw std::invalid_argument("dense LU: right-hand side too short");
  const int size = as_int(n_), nrhs = 1, lda = as_int(lu_.rows()), ldb = as_int(b.size());
  int info = 0;
  dgetrs_("N", &size, &nrhs, lu_.data(), &lda, pivots_.data(), b.data(), &ldb, &info, 1);
  if (info != 0) throw std::invalid_argument("dense LU: dgetrs rejected argument " + std::to_string(-info));
}

}  // namespace rollnoise
