#include "contact/pmatrix_lcp.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/LU>

#include "contact/block_pivoting_exchange.hpp"

namespace rollnoise {
namespace {

// Block principal pivoting from the basic set in result.basic. solve_basic(basic, active, z, w,
// tolerance, fresh) puts M_AA⁻¹(−q_A) on the basic indices A of z and zeros elsewhere (z holds
// the last iterate on entry); `fresh` asks it not to reuse factors, when the last solution left a
// residual beyond round-off on A. It may stop short of M_AA⁻¹(−q_A) once every sign test below
// (z_i < −tolerance on A, w_i < −tolerance off it) is decided as it would be for the exact
// solution and some index is infeasible: it then returns true with w = M·z + q off A, and this
// iteration exchanges exactly the indices that the exact solution's would (with every test decided
// feasible, z need only meet the KKT conditions: conjugate_gradients). multiply(z, w) sets
// w = M·z.
template <class SolveBasic, class Multiply>
void pivot(const Eigen::VectorXd& q, std::vector<Eigen::Index>& active, PMatrixLcpResult& result,
           SolveBasic&& solve_basic, Multiply&& multiply) {
  const Eigen::Index n = q.size();
  std::vector<char>& basic = result.basic;
  const double scale = q.cwiseAbs().maxCoeff() + 1e-300;
  const double tolerance = 1e-13 * scale;
  BlockPivotingExchange exchange(n);
  const int max_iterations = static_cast<int>(10 * n + 100);
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    active.clear();
    for (Eigen::Index i = 0; i < n; ++i)
      if (basic[static_cast<std::size_t>(i)]) active.push_back(i);
    // w = M·z + q (z is zero off the basic set). A residual on the basic set beyond round-off
    // means the factors in solve_basic went stale: solve once more, fresh.
    for (const bool fresh : {false, true}) {
      if (solve_basic(basic, active, result.z, result.w, tolerance, fresh)) break;
      multiply(result.z, active, result.w);
      result.w += q;
      double residual = 0.0;
      for (const Eigen::Index a : active) residual = std::max(residual, std::abs(result.w(a)));
      if (residual <= 1e-9 * scale) break;
    }
    for (const Eigen::Index a : active) result.w(a) = 0.0;  // zero by construction
    // Infeasible indices: negative z among the basic ones, negative w among the others.
    Eigen::Index infeasible = 0;
    Eigen::Index last = -1;
    for (Eigen::Index i = 0; i < n; ++i) {
      const bool bad = basic[static_cast<std::size_t>(i)] ? result.z(i) < -tolerance : result.w(i) < -tolerance;
      if (bad) {
        ++infeasible;
        last = i;
      }
    }
    result.iterations = iteration;
    if (infeasible == 0) {
      result.z = result.z.cwiseMax(0.0);
      return;
    }
    exchange.exchange(basic, infeasible, last, [&](Eigen::Index i) {
      return basic[static_cast<std::size_t>(i)] ? result.z(i) < -tolerance : result.w(i) < -tolerance;
    });
  }
  throw std::runtime_error("P-matrix LCP did not converge in " + std::to_string(max_iterations) +
                           " iterations (n = " + std::to_string(n) + "): is the matrix a P-matrix?");
}

// w = M·z from the columns of the basic set alone (z is zero elsewhere).
void multiply_basic_columns(const Eigen::MatrixXd& m, const Eigen::VectorXd& z, const std::vector<Eigen::Index>& active,
                            Eigen::VectorXd& w) {
  w.setZero();
  for (const Eigen::Index a : active) w.noalias() += m.col(a) * z(a);
}

// What the conjugate gradients' bounds need of M, in one pass over its columns without an n × n
// temporary (M is 87 MB on the 50 km/h grid's 3300 window points, and each temporary as much in
// page faults): whether M is symmetric to round-off; Gershgorin's radius of D^{-1/2}·M·D^{-1/2}
// − I (D = diag M: the scaled matrix's eigenvalues lie within it of 1; infinity when some
// M_ii ≤ 0); and of the rows without their diagonal, the largest 2-norm and 1-norm, and the
// least margin M_ii − Σ_{j≠i} |M_ij|. Each row's sums run over j in order.
struct MatrixBounds {
  bool symmetric = false;
  double radius = INFINITY, row_norm = 0.0, row_sum = 0.0, dominance = 0.0;
};

MatrixBounds matrix_bounds(const Eigen::MatrixXd& m) {
  const Eigen::Index n = m.rows();
  const Eigen::VectorXd d = m.diagonal();
  MatrixBounds bounds;
  double largest = 0.0, asymmetry = 0.0;
  Eigen::VectorXd scaled = Eigen::VectorXd::Zero(n), squares = Eigen::VectorXd::Zero(n), sums = Eigen::VectorXd::Zero(n);
  const bool positive = n > 0 && d.minCoeff() > 0.0;
  const Eigen::VectorXd root = positive ? Eigen::VectorXd(d.cwiseSqrt().cwiseInverse()) : Eigen::VectorXd::Zero(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double* column = m.col(j).data();
    for (Eigen::Index i = 0; i < n; ++i) {
      largest = std::max(largest, std::abs(column[i]));
      if (i < j) asymmetry = std::max(asymmetry, std::abs(column[i] - m(j, i)));
      if (i == j) continue;
      scaled(i) += std::abs(column[i]) * root(j);
      squares(i) += column[i] * column[i];
      sums(i) += std::abs(column[i]);
    }
  }
  bounds.symmetric = asymmetry <= 1e-14 * largest;
  if (positive) bounds.radius = scaled.cwiseProduct(root).maxCoeff();
  bounds.row_norm = squares.cwiseSqrt().maxCoeff();
  bounds.row_sum = sums.maxCoeff();
  bounds.dominance = (d - sums).minCoeff();
  return bounds;
}

std::vector<char> penetrating(const Eigen::VectorXd& q) {
  std::vector<char> basic(static_cast<std::size_t>(q.size()), 0);
  for (Eigen::Index i = 0; i < q.size(); ++i) basic[static_cast<std::size_t>(i)] = q(i) < 0.0;
  return basic;
}

}  // namespace

PMatrixLcpResult solve_pmatrix_lcp(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                                   const std::vector<char>* start) {
  const Eigen::Index n = q.size();
  if (m.rows() != n || m.cols() != n) throw std::invalid_argument("P-matrix LCP: sizes differ");
  // Start from the guess, or from the points that penetrate with no force.
  PMatrixLcpResult result{Eigen::VectorXd::Zero(n), q, 0, {}};
  result.basic = start && static_cast<Eigen::Index>(start->size()) == n ? *start : penetrating(q);
  std::vector<Eigen::Index> active;
  pivot(q, active, result,
        [&m, &q](const std::vector<char>&, const std::vector<Eigen::Index>& set, Eigen::VectorXd& z, Eigen::VectorXd&,
                 double, bool) {
          const auto p = static_cast<Eigen::Index>(set.size());
          z.setZero();
          if (p == 0) return false;
          Eigen::MatrixXd block(p, p);
          Eigen::VectorXd rhs(p);
          for (Eigen::Index a = 0; a < p; ++a) {
            rhs(a) = -q(set[a]);
            for (Eigen::Index b = 0; b < p; ++b) block(a, b) = m(set[a], set[b]);
          }
          const Eigen::VectorXd za = block.partialPivLu().solve(rhs);
          for (Eigen::Index a = 0; a < p; ++a) z(set[a]) = za(a);
          return false;
        },
        [&m](const Eigen::VectorXd& z, const std::vector<Eigen::Index>& set, Eigen::VectorXd& w) {
          multiply_basic_columns(m, z, set, w);
        });
  return result;
}

PMatrixLcpSolver::PMatrixLcpSolver(Eigen::MatrixXd m, Eigen::Index capacity, std::optional<ContactWindow> window)
    : m_(std::make_shared<const Eigen::MatrixXd>(std::move(m))), factor_(m_, capacity) {
  const Eigen::Index n = m_->rows();
  if (window) {
    if (Eigen::Index{window->window} * window->lateral != n)
      throw std::invalid_argument("P-matrix LCP: the window's points differ from the matrix's size");
    product_ = std::make_unique<WindowConvolution>(*m_, window->window, window->lateral);
    // The condition number of the scaled matrix is at most (1 + radius)/(1 − radius) ≤ 25, and
    // its smallest eigenvalue, and by Cauchy's interlacing that of every principal block, at
    // least 1 − radius: the bound on the conjugate gradients' error (conjugate_gradients).
    const MatrixBounds bounds = matrix_bounds(*m_);
    const double radius = bounds.radius;
    iterative_ = bounds.symmetric && radius < 1.0 && (1.0 + radius) / (1.0 - radius) <= 25.0;
    if (iterative_) {
      error_per_residual_ = 1.0 / ((1.0 - radius) * std::sqrt(m_->diagonal().minCoeff()));
      // Off the block, w's error sums M(i, a)·e_a over a ≠ i: M's rows without their diagonal.
      coupling_row_norm_ = bounds.row_norm;
      coupling_row_sum_ = bounds.row_sum;
      // Varah's bound (Linear Algebra Appl. 11 (1975) 3–5): a strictly row diagonally dominant
      // block has ‖M_AA⁻¹‖∞ ≤ 1/min_i (M_ii − Σ_{j≠i} |M_ij|), a margin that a principal block
      // only widens. Without dominance only the 2-norm bound is used.
      error_per_max_residual_ = bounds.dominance > 0.0 ? 1.0 / bounds.dominance : INFINITY;
    }
  }
  result_.z = Eigen::VectorXd::Zero(n);
  result_.w.resize(n);
  shifted_.resize(static_cast<std::size_t>(n));
  active_.reserve(static_cast<std::size_t>(n));
  last_z_ = Eigen::VectorXd::Zero(n);
  shifted_z_ = last_z_;
  inverse_diagonal_ = m_->diagonal().cwiseInverse();
  mask_ = r_ = s_ = p_ = mp_ = mz_ = last_z_;
}

PMatrixLcpSolver::~PMatrixLcpSolver() = default;

void PMatrixLcpSolver::warm_start(const std::vector<char>& basic) {
  if (static_cast<Eigen::Index>(basic.size()) != m_->rows()) throw std::invalid_argument("P-matrix LCP: one flag per index");
  result_.basic = basic;
  last_z_.setZero();
}

void PMatrixLcpSolver::relabel(const std::vector<Eigen::Index>& new_index, bool matrix_unchanged) {
  if (static_cast<Eigen::Index>(new_index.size()) != m_->rows()) throw std::invalid_argument("P-matrix LCP: one new index per index");
  if (result_.basic.empty()) return;
  std::fill(shifted_.begin(), shifted_.end(), 0);
  shifted_z_.setZero();
  for (std::size_t i = 0; i < new_index.size(); ++i)
    if (const Eigen::Index to = new_index[i]; to >= 0) {
      shifted_[static_cast<std::size_t>(to)] = result_.basic[i];
      shifted_z_(to) = last_z_(static_cast<Eigen::Index>(i));
    }
  std::swap(shifted_, result_.basic);
  std::swap(shifted_z_, last_z_);
  if (matrix_unchanged) factor_.relabel(new_index);
  else factor_.invalidate();
}

const PMatrixLcpResult& PMatrixLcpSolver::solve(const Eigen::VectorXd& q) {
  if (q.size() != m_->rows()) throw std::invalid_argument("P-matrix LCP: sizes differ");
  if (result_.basic.empty()) result_.basic = penetrating(q);
  result_.z = last_z_;  // the warm start of the conjugate gradients
  mz_valid_ = false;    // M·z is for the last q's window (relabel moves z)
  if (iterative_ && decide_early_ && correct_start_) correct_start(q);
  pivot(q, active_, result_,
        [this, &q](const std::vector<char>& basic, const std::vector<Eigen::Index>&, Eigen::VectorXd& z,
                   Eigen::VectorXd& w, double tolerance, bool fresh) {
          if (iterative_ && !fresh) {
            const Cg outcome = conjugate_gradients(basic, q, z, w, tolerance);
            if (outcome == Cg::decided) return true;
            if (outcome == Cg::converged) return false;
          }
          if (fresh) factor_.invalidate();
          factor_.solve(basic, q, z);
          mz_valid_ = false;
          return false;
        },
        [this](const Eigen::VectorXd& z, const std::vector<Eigen::Index>& active, Eigen::VectorXd& w) {
          if (product_) product_->apply(z, w);
          else multiply_basic_columns(*m_, z, active, w);
        });
  last_z_ = result_.z;
  return result_;
}

void PMatrixLcpSolver::correct_start(const Eigen::VectorXd& q) {
  // The last step's set, moved with the road, misses the points that touch anew and keeps some
  // that lift off: 2.7 pivoting iterations a step on plate_rough_80kmh, each a solve of its
  // block. Read the warm forces' gaps instead (the product that the first solve needs anyway):
  // a point off the set that penetrates under them enters, and a point on it whose force one
  // Jacobi step on its residual would make negative leaves. A guess of the first set only: the
  // pivoting that follows is the same, and so is the solution (unique for a P-matrix).
  std::vector<char>& basic = result_.basic;
  Eigen::VectorXd& z = result_.z;
  const Eigen::Index n = q.size();
  for (Eigen::Index i = 0; i < n; ++i)
    if (!basic[static_cast<std::size_t>(i)]) z(i) = 0.0;
  product_->apply(z, mz_);
  const double tolerance = 1e-13 * (q.cwiseAbs().maxCoeff() + 1e-300);
  for (Eigen::Index i = 0; i < n; ++i) {
    char& on = basic[static_cast<std::size_t>(i)];
    const double gap = mz_(i) + q(i);
    if (!on) on = gap < -tolerance;
    else on = z(i) - gap * inverse_diagonal_(i) >= 0.0;
  }
  mz_valid_ = true;  // for z as it is: conjugate_gradients takes the leaving points' columns off
}

PMatrixLcpSolver::Cg PMatrixLcpSolver::conjugate_gradients(const std::vector<char>& basic, const Eigen::VectorXd& q,
                                                           Eigen::VectorXd& z, Eigen::VectorXd& w, double tolerance) {
  // Jacobi-preconditioned CG on the basic block, the other indices masked out; the products by
  // FFT, kept whole (mz_ = M·z over all indices, updated with each step as r is) so that w off
  // the block is known at every iterate without a product of its own.
  const Eigen::Index n = q.size();
  // M·z of the last pivoting iteration's z, carried along: z loses the indices that left the
  // block (those that enter had z = 0), whose columns of M are taken off when they are fewer
  // than a product's cost (a column is n multiply-adds from the kernel along x, which stays in
  // cache; a product a few dozen n).
  bool by_columns = mz_valid_ && decide_early_;
  if (by_columns) {
    Eigen::Index leaving = 0;
    for (Eigen::Index i = 0; i < n; ++i) leaving += !basic[static_cast<std::size_t>(i)] && z(i) != 0.0;
    by_columns = leaving <= kLeavingColumns;
  }
  if (by_columns)
    for (Eigen::Index i = 0; i < n; ++i)
      if (!basic[static_cast<std::size_t>(i)] && z(i) != 0.0) product_->subtract_column(i, z(i), mz_);
  for (Eigen::Index i = 0; i < n; ++i) mask_(i) = basic[static_cast<std::size_t>(i)] ? 1.0 : 0.0;
  z.array() *= mask_.array();
  if (!by_columns) product_->apply(z, mz_);
  mz_valid_ = false;
  const double scale = q.cwiseAbs().maxCoeff() + 1e-300;
  const double stop = 1e-13 * scale;
  // Once every sign is decided feasible, the residual need only be this: the KKT conditions
  // hold to about 1e-11 scaled (8e-12 on the plate's rolling steps), a tenth of the 1e-10
  // required, and z is within a few 1e-11 of the fully converged one.
  const double close = 1e-11 * scale;
  // Round-off of the FFT products and of mz_'s updates (relative 1e-15 or so) is far inside this.
  const double margin = 1e-12 * scale;
  r_ = (-q - mz_).cwiseProduct(mask_);
  if (r_.cwiseAbs().maxCoeff() <= stop) {
    mz_valid_ = true;
    return Cg::converged;
  }
  s_ = r_.cwiseProduct(inverse_diagonal_);
  p_ = s_;
  double rs = r_.dot(s_);
  for (int iteration = 0; iteration < 500; ++iteration) {
    product_->apply(p_, mp_);
    const double curvature = p_.dot(mp_);  // p is zero off the block
    if (!(curvature > 0.0)) return Cg::failed;
    const double alpha = rs / curvature;
    z.noalias() += alpha * p_;
    mz_.noalias() += alpha * mp_;
    r_.noalias() -= alpha * mp_.cwiseProduct(mask_);
    ++cg_iterations_;
    const double largest = r_.cwiseAbs().maxCoeff();
    if (largest <= stop) {
      mz_valid_ = true;
      return Cg::converged;
    }
    s_ = r_.cwiseProduct(inverse_diagonal_);
    const double next = r_.dot(s_);
    // The error e = M_AA⁻¹·r of z on the block: ‖e‖₂ ≤ ‖D^{-1/2}‖·‖S_AA⁻¹‖·‖D^{-1/2}r‖₂ with
    // S = D^{-1/2}·M·D^{-1/2} (D = diag M), and ‖D^{-1/2}r‖₂² = rᵀD⁻¹r = `next`; and ‖e‖∞ ≤
    // ‖M_AA⁻¹‖∞·‖r‖∞ by Varah's bound. Off the block w's error is M_NA·e, at most ‖e‖₂ times the
    // largest 2-norm, or ‖e‖∞ times the largest 1-norm, of M's rows without their diagonal. If
    // every sign test of the pivoting is decided beyond these bounds, and some index is
    // infeasible, the exact solve would exchange the same indices: stop here.
    const double error_2 = std::sqrt(std::max(next, 0.0)) * error_per_residual_;
    const double error_max = largest * error_per_max_residual_;
    const double z_error = std::min(error_2, error_max) + margin;
    const double w_error = std::min(coupling_row_norm_ * error_2, coupling_row_sum_ * error_max) + margin;
    if (decide_early_) {
      const Signs signs = decide_signs(basic, q, z, z_error, w_error, tolerance);
      if (signs == Signs::infeasible) {
        w = mz_ + q;
        mz_valid_ = true;
        return Cg::decided;
      }
      // Every index feasible as for the exact solution: the LCP's solution is this block's, and
      // z need only meet the KKT conditions (to 1e-10, scaled) with a margin.
      if (signs == Signs::feasible && largest <= close) {
        mz_valid_ = true;
        return Cg::converged;
      }
    }
    p_ = s_ + (next / rs) * p_;
    rs = next;
  }
  return Cg::failed;
}

PMatrixLcpSolver::Signs PMatrixLcpSolver::decide_signs(const std::vector<char>& basic, const Eigen::VectorXd& q,
                                                       const Eigen::VectorXd& z, double z_error, double w_error,
                                                       double tolerance) const {
  bool infeasible = false;
  const char* on = basic.data();
  const double *zi = z.data(), *mzi = mz_.data(), *qi = q.data();
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    const bool on_block = on[i] != 0;
    const double value = on_block ? zi[i] : mzi[i] + qi[i];
    const double error = on_block ? z_error : w_error;
    if (value - error >= -tolerance) continue;    // feasible, whatever the error
    if (value + error < -tolerance) {             // infeasible, whatever the error
      infeasible = true;
      continue;
    }
    return Signs::undecided;
  }
  return infeasible ? Signs::infeasible : Signs::feasible;
}

bool matrix_unchanged_by(const Eigen::MatrixXd& m, const std::vector<Eigen::Index>& new_index, double tolerance) {
  if (static_cast<Eigen::Index>(new_index.size()) != m.rows()) return false;
  const double limit = tolerance * m.cwiseAbs().maxCoeff();
  for (Eigen::Index b = 0; b < m.cols(); ++b) {
    const Eigen::Index nb = new_index[static_cast<std::size_t>(b)];
    if (nb < 0) continue;
    for (Eigen::Index a = 0; a < m.rows(); ++a) {
      const Eigen::Index na = new_index[static_cast<std::size_t>(a)];
      if (na >= 0 && std::abs(m(na, nb) - m(a, b)) > limit) return false;
    }
  }
  return true;
}

}  // namespace rollnoise
