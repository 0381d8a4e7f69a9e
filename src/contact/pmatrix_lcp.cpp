#include "contact/pmatrix_lcp.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/LU>

#include "contact/block_pivoting_exchange.hpp"
#include "core/avx_support.hpp"

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

// The pivoting's sign tests on one side of the block (z on it, w = M·z + q off it) under one
// error bound e that is known only once the pass over the values is done: a value v is feasible
// whatever its error when v − e ≥ −tolerance, infeasible when v + e < −tolerance, and otherwise
// undecided. Both sides of each test grow with v (rounding is monotone), so of all the values
// only three can decide the outcome: the least at or above −tolerance (the first to be
// undecided from above), the greatest below it (the first from below), and the least (the first
// to be infeasible). The outcome is the same as testing every value, bit for bit.
class SignRange {
 public:
  enum class Outcome { undecided, infeasible, feasible };
  explicit SignRange(double tolerance) noexcept : tolerance_(tolerance) {}
  double tolerance() const noexcept { return tolerance_; }
  void add(double v) noexcept {
    if (v >= -tolerance_) {
      least_at_or_above_ = std::min(least_at_or_above_, v);
    } else if (v < -tolerance_) {
      greatest_below_ = std::max(greatest_below_, v);
      least_ = std::min(least_, v);
    } else {
      unordered_ = true;  // NaN: never decided
    }
  }
  // The three values of another pass over values of this side (four lanes of one, say).
  void absorb(double least_at_or_above, double greatest_below, double least, bool unordered) noexcept {
    least_at_or_above_ = std::min(least_at_or_above_, least_at_or_above);
    greatest_below_ = std::max(greatest_below_, greatest_below);
    least_ = std::min(least_, least);
    unordered_ = unordered_ || unordered;
  }
  Outcome outcome(double error) const noexcept {
    if (unordered_ || least_at_or_above_ - error < -tolerance_ || greatest_below_ + error >= -tolerance_)
      return Outcome::undecided;
    return least_ + error < -tolerance_ ? Outcome::infeasible : Outcome::feasible;
  }

 private:
  double tolerance_;
  double least_at_or_above_ = INFINITY, greatest_below_ = -INFINITY, least_ = INFINITY;
  bool unordered_ = false;
};

// Both sides' outcomes: undecided if either is, else infeasible if either is.
SignRange::Outcome combine(SignRange::Outcome a, SignRange::Outcome b) noexcept {
  using enum SignRange::Outcome;
  if (a == undecided || b == undecided) return undecided;
  return a == infeasible || b == infeasible ? infeasible : feasible;
}

// One conjugate-gradient step's pass over the window (conjugate_gradients): z += α·p and
// M·z += α·M·p everywhere; on the block (`on`) r −= α·M·p, s = D⁻¹·r and max |r|; off it r and s
// stay +0. The sign tests' values (z on the block, w = M·z + q off it) go into `on_range` and
// `off_range`. Returns max |r| on the block.
struct CgPass {
  Eigen::Index n;
  double alpha;
  const char* on;
  const double *on_bits, *p, *mp, *q, *inverse_diagonal;
  double *z, *mz, *r, *s;
};

double cg_pass_scalar(const CgPass& c, Eigen::Index begin, SignRange& on_range, SignRange& off_range) {
  double largest = 0.0;
  for (Eigen::Index i = begin; i < c.n; ++i) {
    c.z[i] += c.alpha * c.p[i];
    c.mz[i] += c.alpha * c.mp[i];
    if (c.on[i]) {
      c.r[i] -= c.alpha * c.mp[i];
      c.s[i] = c.r[i] * c.inverse_diagonal[i];
      largest = std::max(largest, std::abs(c.r[i]));
      on_range.add(c.z[i]);
    } else {
      off_range.add(c.mz[i] + c.q[i]);
    }
  }
  return largest;
}

#if defined(ROLLNOISE_AVX_PATHS)
// cg_pass_scalar four values at a time, for processors with AVX (asked once, at construction):
// per value the same multiplications, additions and comparisons (no fused multiply-add), so the
// same bits; the block is selected by `on_bits` (all bits set on it, zero off it). 4 times fewer
// instructions than the scalar loop, whose branches and sign tests do not vectorise.
// a where `mask` has all bits set, b where it has none (bitwise: GCC scalarises blendv with a
// constant operand).
__attribute__((target("avx"))) inline __m256d select(__m256d mask, __m256d a, __m256d b) {
  return _mm256_or_pd(_mm256_and_pd(mask, a), _mm256_andnot_pd(mask, b));
}

__attribute__((target("avx"))) double cg_pass_avx(const CgPass& c, SignRange& on_range, SignRange& off_range) {
  const __m256d alpha = _mm256_set1_pd(c.alpha), limit = _mm256_set1_pd(-on_range.tolerance());
  const __m256d inf = _mm256_set1_pd(INFINITY), minus_inf = _mm256_set1_pd(-INFINITY);
  const __m256d magnitude = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffffLL));
  __m256d largest = _mm256_setzero_pd(), unordered = _mm256_setzero_pd();
  __m256d on_above = inf, on_below = minus_inf, on_least = inf, off_above = inf, off_below = minus_inf, off_least = inf;
  // The pointers in registers (stores through them could otherwise alias c).
  const double *on_bits = c.on_bits, *p = c.p, *mpv = c.mp, *q = c.q, *inverse_diagonal = c.inverse_diagonal;
  double *zv = c.z, *mzv = c.mz, *rv = c.r, *sv = c.s;
  Eigen::Index i = 0;
  for (; i + 4 <= c.n; i += 4) {
    const __m256d on = _mm256_loadu_pd(on_bits + i);
    const __m256d mp = _mm256_loadu_pd(mpv + i);
    const __m256d z = _mm256_add_pd(_mm256_loadu_pd(zv + i), _mm256_mul_pd(alpha, _mm256_loadu_pd(p + i)));
    const __m256d mz = _mm256_add_pd(_mm256_loadu_pd(mzv + i), _mm256_mul_pd(alpha, mp));
    const __m256d r = _mm256_and_pd(_mm256_sub_pd(_mm256_loadu_pd(rv + i), _mm256_mul_pd(alpha, mp)), on);
    _mm256_storeu_pd(zv + i, z);
    _mm256_storeu_pd(mzv + i, mz);
    _mm256_storeu_pd(rv + i, r);
    _mm256_storeu_pd(sv + i, _mm256_mul_pd(r, _mm256_loadu_pd(inverse_diagonal + i)));
    largest = _mm256_max_pd(largest, _mm256_and_pd(r, magnitude));
    const __m256d v = select(on, z, _mm256_add_pd(mz, _mm256_loadu_pd(q + i)));
    unordered = _mm256_or_pd(unordered, _mm256_cmp_pd(v, v, _CMP_UNORD_Q));
    const __m256d above = _mm256_cmp_pd(v, limit, _CMP_GE_OQ), below = _mm256_cmp_pd(v, limit, _CMP_LT_OQ);
    const __m256d on_below_mask = _mm256_and_pd(on, below), off_below_mask = _mm256_andnot_pd(on, below);
    on_above = _mm256_min_pd(on_above, select(_mm256_and_pd(on, above), v, inf));
    on_below = _mm256_max_pd(on_below, select(on_below_mask, v, minus_inf));
    on_least = _mm256_min_pd(on_least, select(on_below_mask, v, inf));
    off_above = _mm256_min_pd(off_above, select(_mm256_andnot_pd(on, above), v, inf));
    off_below = _mm256_max_pd(off_below, select(off_below_mask, v, minus_inf));
    off_least = _mm256_min_pd(off_least, select(off_below_mask, v, inf));
  }
  alignas(32) double lanes[8][4];
  for (const auto& [k, value] : {std::pair{0, largest}, {1, unordered}, {2, on_above}, {3, on_below}, {4, on_least},
                                 {5, off_above}, {6, off_below}, {7, off_least}})
    _mm256_store_pd(lanes[k], value);
  double most = 0.0;
  for (int lane = 0; lane < 4; ++lane) {
    most = std::max(most, lanes[0][lane]);
    const bool nan = std::bit_cast<std::uint64_t>(lanes[1][lane]) != 0;
    on_range.absorb(lanes[2][lane], lanes[3][lane], lanes[4][lane], nan);
    off_range.absorb(lanes[5][lane], lanes[6][lane], lanes[7][lane], nan);
  }
  return std::max(most, cg_pass_scalar(c, i, on_range, off_range));
}
#endif

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
  leaving_.reserve(static_cast<std::size_t>(n));
  last_z_ = Eigen::VectorXd::Zero(n);
  shifted_z_ = older_z_ = last_z_;
  inverse_diagonal_ = m_->diagonal().cwiseInverse();
  r_ = s_ = p_ = mp_ = mz_ = last_z_;
  on_bits_.assign(static_cast<std::size_t>(n), 0.0);
  use_avx(true);
}

PMatrixLcpSolver::~PMatrixLcpSolver() = default;

bool PMatrixLcpSolver::use_avx(bool on) noexcept {
  avx_ = avx_available(on);
  return avx_;
}

void PMatrixLcpSolver::warm_start(const std::vector<char>& basic) {
  if (static_cast<Eigen::Index>(basic.size()) != m_->rows()) throw std::invalid_argument("P-matrix LCP: one flag per index");
  result_.basic = basic;
  last_z_.setZero();
  older_z_.setZero();
  solves_ = 0;
}

void PMatrixLcpSolver::relabel(const std::vector<Eigen::Index>& new_index, bool matrix_unchanged) {
  if (static_cast<Eigen::Index>(new_index.size()) != m_->rows()) throw std::invalid_argument("P-matrix LCP: one new index per index");
  if (result_.basic.empty()) return;
  std::fill(shifted_.begin(), shifted_.end(), 0);
  for (Eigen::VectorXd* z : {&last_z_, &older_z_}) {
    shifted_z_.setZero();
    for (std::size_t i = 0; i < new_index.size(); ++i)
      if (const Eigen::Index to = new_index[i]; to >= 0) shifted_z_(to) = (*z)(static_cast<Eigen::Index>(i));
    std::swap(shifted_z_, *z);
  }
  for (std::size_t i = 0; i < new_index.size(); ++i)
    if (const Eigen::Index to = new_index[i]; to >= 0) shifted_[static_cast<std::size_t>(to)] = result_.basic[i];
  std::swap(shifted_, result_.basic);
  if (matrix_unchanged) factor_.relabel(new_index);
  else factor_.invalidate();
}

const PMatrixLcpResult& PMatrixLcpSolver::solve(const Eigen::VectorXd& q) {
  if (q.size() != m_->rows()) throw std::invalid_argument("P-matrix LCP: sizes differ");
  if (result_.basic.empty()) result_.basic = penetrating(q);
  result_.z = last_z_;  // the warm start of the conjugate gradients
  // A point's force moves smoothly along its path through the patch (the relabelling keeps each
  // index on the same road position), so where it was in contact at both of the last two steps
  // the straight line through their forces, z = 2·z₋₁ − z₋₂ (clipped at 0), starts the
  // conjugate gradients closer than z₋₁ alone: the error left is second order in the step
  // rather than first. A first guess only: the solution and the pivoting are the exact solves'.
  if (iterative_ && decide_early_ && correct_start_ && solves_ >= 2)
    for (Eigen::Index i = 0; i < q.size(); ++i)
      if (last_z_(i) > 0.0 && older_z_(i) > 0.0) result_.z(i) = std::max(2.0 * last_z_(i) - older_z_(i), 0.0);
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
  std::swap(older_z_, last_z_);
  last_z_ = result_.z;
  ++solves_;
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
  const char* on = basic.data();
  bool by_columns = mz_valid_ && decide_early_;
  if (by_columns) {
    leaving_.clear();
    for (Eigen::Index i = 0; i < n; ++i)
      if (!on[i] && z(i) != 0.0) leaving_.push_back(i);
    by_columns = static_cast<Eigen::Index>(leaving_.size()) <= kLeavingColumns;
    if (by_columns)
      for (const Eigen::Index i : leaving_) product_->subtract_column(i, z(i), mz_);
  }
  // Off the block z, r, s and p are +0 (selected, not multiplied by a mask, whose products would
  // leave −0 where z < 0: a sign that the forces' files would show).
  for (Eigen::Index i = 0; i < n; ++i)
    if (!on[i]) z(i) = 0.0;
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
  // r = −q − M·z, s = D⁻¹·r and p = s on the block, +0 off it, and the block's mask for the pass.
  double first_largest = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const bool in = on[i] != 0;
    r_(i) = in ? -q(i) - mz_(i) : 0.0;
    s_(i) = p_(i) = r_(i) * inverse_diagonal_(i);
    on_bits_[static_cast<std::size_t>(i)] = in ? std::bit_cast<double>(~std::uint64_t{0}) : 0.0;
    first_largest = std::max(first_largest, std::abs(r_(i)));
  }
  if (first_largest <= stop) {
    mz_valid_ = true;
    return Cg::converged;
  }
  double rs = r_.dot(s_);
  double* pi = p_.data();
  const double* si = s_.data();
  for (int iteration = 0; iteration < 500; ++iteration) {
    product_->apply(p_, mp_);
    const double curvature = p_.dot(mp_);  // p is zero off the block
    if (!(curvature > 0.0)) return Cg::failed;
    const double alpha = rs / curvature;
    // One pass for the step's updates (z += α·p, M·z += α·M·p, r −= α·M·p on the block, s = D⁻¹r)
    // and for what the sign tests need (SignRange: the pivoting's sign tests, whose error
    // bounds wait on this pass's ‖r‖). Off the block r, s and p stay zero. Each value gets
    // the same operations as separate passes would give it, so the iterates keep their bits.
    SignRange on_range(tolerance), off_range(tolerance);
    const CgPass pass{n,         alpha,      on,       on_bits_.data(), p_.data(), mp_.data(), q.data(),
                      inverse_diagonal_.data(), z.data(), mz_.data(), r_.data(), s_.data()};
#if defined(ROLLNOISE_AVX_PATHS)
    const double largest = avx_ ? cg_pass_avx(pass, on_range, off_range) : cg_pass_scalar(pass, 0, on_range, off_range);
#else
    const double largest = cg_pass_scalar(pass, 0, on_range, off_range);
#endif
    ++cg_iterations_;
    if (largest <= stop) {
      mz_valid_ = true;
      return Cg::converged;
    }
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
      const SignRange::Outcome signs = combine(on_range.outcome(z_error), off_range.outcome(w_error));
      if (signs == SignRange::Outcome::infeasible) {
        w = mz_ + q;
        mz_valid_ = true;
        return Cg::decided;
      }
      // Every index feasible as for the exact solution: the LCP's solution is this block's, and
      // z need only meet the KKT conditions (to 1e-10, scaled) with a margin.
      if (signs == SignRange::Outcome::feasible && largest <= close) {
        mz_valid_ = true;
        return Cg::converged;
      }
    }
    const double beta = next / rs;
    for (Eigen::Index i = 0; i < n; ++i) pi[i] = si[i] + beta * pi[i];
    rs = next;
  }
  return Cg::failed;
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
