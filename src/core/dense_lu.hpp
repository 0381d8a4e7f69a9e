#pragma once
// The LU factorisation with partial pivoting of a dense square matrix of any size up to a
// capacity fixed at construction, in storage allocated once: LAPACK's dgetrf/dgetrs (OpenBLAS,
// single-threaded: blas_threads.hpp), so that a solver refactorising inside a time-step loop
// allocates nothing there. About twice the speed of Eigen's portable kernels at the contact's
// sizes (n = 400–1000: 7 ms against 15 ms at n = 700 on a 2-core machine).
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

class DenseLu {
 public:
  explicit DenseLu(Eigen::Index capacity);

  // Factorises the n × n matrix written into matrix() (top-left block) beforehand. Throws
  // std::domain_error if it is exactly singular.
  void factorise(Eigen::Index n);
  // The storage to fill before factorise(n): capacity × capacity, column-major; only the
  // top-left n × n block is used.
  Eigen::MatrixXd& matrix() noexcept { return lu_; }

  // Overwrites the first `columns` columns of b (rows 0…n−1, leading dimension b.rows()) with
  // A⁻¹·b.
  void solve_in_place(Eigen::MatrixXd& b, Eigen::Index first_column, Eigen::Index columns) const;
  void solve_in_place(Eigen::VectorXd& b) const;

  Eigen::Index size() const noexcept { return n_; }
  Eigen::Index capacity() const noexcept { return lu_.rows(); }

 private:
  Eigen::MatrixXd lu_;
  std::vector<int> pivots_;
  Eigen::Index n_ = 0;
};

}  // namespace rollnoise
