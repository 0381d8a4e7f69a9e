#pragma once
// The LCP  z ≥ 0, w = M·z + q ≥ 0, zᵀw = 0  for a P-matrix M that need not be symmetric, such as
// the compliance of a rolling, damped tyre summed over all lags (the steady-rolling problem;
// damping makes it non-symmetric). Every P-matrix LCP has exactly one solution.
//
// Block principal pivoting (Júdice & Pires, Comput. Oper. Res. 21 (1994) 587–596): exchange all
// infeasible indices at once while their number falls, and fall back to Murty's single
// least-index pivot, which terminates finitely for P-matrices, when it does not. Each
// iteration solves the active block with a dense LU.
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

struct PMatrixLcpResult {
  Eigen::VectorXd z;  // the solution
  Eigen::VectorXd w;  // M·z + q
  int iterations = 0;
  std::vector<char> basic;  // the final set of indices with z free (w = 0)
};

// `start`: a first guess of the basic set (for example the last solution's, for a nearby q);
// without one, the indices with q < 0.
PMatrixLcpResult solve_pmatrix_lcp(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                                   const std::vector<char>* start = nullptr);

}  // namespace rollnoise
