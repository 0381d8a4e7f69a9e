#include "contact/nonlinear_spring_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Eigenvalues>
#include <kinsol/kinsol.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

// Formulation. The per-point coordinate solved for is not δ itself but
//   y_p = δ_p + A_pp·F_p(δ_p)                (the displacement of point p under its own force),
// a strictly increasing, odd function of δ_p with the same sign, so y_p ≥ 0 ⟺ δ_p ≥ 0 and the
// complementarity problem is unchanged. Why: in δ alone the problem is strongly nonlinear when
// the springs are stiff against the structure (gap ≈ A·k·δⁿ: Newton from above creeps at the
// linear rate 1 − 1/n, and KINSOL ran out of iterations on stiff springs with a rank-deficient
// A); in y both limits are nearly linear (soft springs: y ≈ δ; stiff: y ≈ A_pp·F), and an
// isolated point is exactly linear, gap_p = q_p + y_p. δ(y) is a scalar inverse (closed form for
// n = 1, 2; a few monotone Newton steps otherwise), with dδ/dy = 1/(1 + A_pp D_p) ∈ (0, 1] and
// dF/dy = D_p dδ/dy ≤ 1/A_pp, D_p = dF_p/dδ_p = n k_p|δ_p|^{n−1}. Like δ (and unlike F) y has a
// finite, nonzero derivative at contact onset for n > 1.
//
// The unknown is x = y/s with a length s = ‖q‖∞, so that KINSOL sees x = O(1). Each point
// contributes one Fischer–Burmeister equation
//   Φ_p(x) = φ(a_p, b_p),  a_p = y_p/s,  b_p = gap_p/s,  φ(a, b) = a + b − √(a² + b²),
// and φ(a, b) = 0 ⟺ a ≥ 0, b ≥ 0, a·b = 0. Φ is dimensionless and O(1), so KINSOL's absolute
// tolerance on ‖Φ‖∞ is a tolerance relative to s. The generalised Jacobian (φ is not
// differentiable at a = b = 0) is
//   ∂Φ/∂x = diag(α) + diag(β)·(A·diag(dF/dy) + diag(dδ/dy)),  α = 1 − a/r,  β = 1 − b/r,  r = |(a, b)|,
// and at a = b = 0 the limit along the direction (1, 1), α = β = 1 − 1/√2, which is an element
// of the generalised derivative. A·diag(dF/dy) + diag(dδ/dy) = (I + A·D)·diag(dδ/dy) is a
// P-matrix (I + A·D is one for A PSD and D ≥ 0, and a positive column scaling keeps that), and
// α, β ≥ 0 with α + β > 0, so this Jacobian is nonsingular everywhere: Newton is well defined.
// After KINSOL a Newton polish in δ on the contact set (gap = 0 where in contact, δ = 0
// elsewhere) takes the solution to round-off; it is kept unless it raises the complementarity
// residual max_p |φ(δ_p/s, gap_p/s)|.

namespace rollnoise {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// KINSOL stops at ‖Φ‖∞ ≤ kFuncTol (relative to s); the polish does the rest, so this need not be
// at round-off, where KINSOL's line search could stall on noise.
constexpr double kFuncTol = 1e-11;
// A step this small (scaled) means stagnation.
constexpr double kStepTol = 1e-15;
// When KINSOL stops without meeting kFuncTol (line search stalled, step too small, iteration
// limit), its iterate is polished and accepted if the residual is at round-off: for stiff
// springs on a rank-deficient A, ‖A‖·‖F‖ ≫ ‖q‖ and the round-off of gap = q + A·F + δ alone
// exceeds kFuncTol·s. The acceptance level is kNoiseFactor times that round-off.
constexpr double kNoiseFactor = 16.0;
constexpr long kMaxIterations = 100;
// KINSOL caps a Newton step at 1000·‖x₀‖ by default, but the solution can lie far from O(1) in
// x (stiff springs on a rank-deficient A: large F whose A·F cancels), and the cap then ends runs
// with KIN_MXNEWT_5X_EXCEEDED. The line search is the safeguard instead.
constexpr double kMaxNewtonStep = 1e10;
constexpr int kMaxPolishSteps = 6;

struct ContextDeleter {
  void operator()(SUNContext context) const noexcept { SUNContext_Free(&context); }
};
struct VectorDeleter {
  void operator()(N_Vector vector) const noexcept { N_VDestroy(vector); }
};
struct MatrixDeleter {
  void operator()(SUNMatrix matrix) const noexcept { SUNMatDestroy(matrix); }
};
struct LinearSolverDeleter {
  void operator()(SUNLinearSolver solver) const noexcept { SUNLinSolFree(solver); }
};
struct KinsolDeleter {
  void operator()(void* memory) const noexcept { KINFree(&memory); }
};

using ContextPtr = std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter>;
using VectorPtr = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter>;
using MatrixPtr = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter>;
using LinearSolverPtr = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, LinearSolverDeleter>;
using KinsolPtr = std::unique_ptr<void, KinsolDeleter>;

template <class T>
T created(T object, const char* what) {
  if (object == nullptr) throw std::runtime_error(std::string("NonlinearSpringContact: could not create ") + what);
  return object;
}

void check(int flag, const char* what) {
  if (flag != 0) {
    throw std::runtime_error(std::string("NonlinearSpringContact: ") + what + " failed (flag " +
                             std::to_string(flag) + ")");
  }
}

std::string flag_name(int flag) {
  // KINSOL returns a malloc'ed string.
  char* name = KINGetReturnFlagName(flag);
  std::string text = name != nullptr ? std::string(name) : std::string("unknown");
  std::free(name);
  return text;
}

// φ(a, b) = a + b − √(a² + b²). For a + b > 0 that difference cancels (a ≫ b > 0 leaves b's
// digits to round-off); (a + b)² − r² = 2ab gives the same value as 2ab/(a + b + r) exactly.
double fischer_burmeister(double a, double b) {
  const double r = std::hypot(a, b);
  return a + b > 0.0 ? 2.0 * a * b / (a + b + r) : a + b - r;
}

}  // namespace

struct NonlinearSpringContact::Impl {
  Impl(Eigen::MatrixXd structural, Eigen::VectorXd stiffness, double exponent, bool require_symmetric);

  // δ_p from y_p: solves δ + c·sign(δ)|δ|ⁿ = y with c = A_pp·k_p.
  double compression_of(double y, Eigen::Index p) const;
  // F_p = k_p·sign(δ_p)|δ_p|ⁿ (the odd extension keeps the map C¹ through δ = 0 while Newton
  // visits δ < 0), D_p = n·k_p|δ_p|^{n−1} and gap = q + A·F + δ for work_delta, into the work_*
  // vectors.
  void evaluate_delta();
  // δ(y) into work_delta, dδ/dy into work_slope, then evaluate_delta().
  void evaluate_coordinate(const Eigen::Ref<const Eigen::VectorXd>& y);
  // max_p |φ(first_p/s, gap_p/s)| with the gap last evaluated.
  double merit(const Eigen::Ref<const Eigen::VectorXd>& first) const;
  // One KINSOL run from the x already in u, then the polish of its iterate into `candidate`;
  // returns the KINSOL flag, or 0 for an iterate accepted at round-off.
  int run_kinsol();
  // eps·(‖q‖∞ + ‖A‖∞‖F‖∞ + ‖δ‖∞): the round-off level of gap at the point last evaluated.
  double gap_noise() const;
  // Newton on the contact set of δ = `point` (updated in place if that lowers the residual).
  void polish(Eigen::VectorXd& point);

  static int residual(N_Vector u_in, N_Vector f, void* data) noexcept;
  static int jacobian(N_Vector u_in, N_Vector f, SUNMatrix j, void* data, N_Vector, N_Vector) noexcept;
  static void error_handler(int code, const char* module, const char* function, char* message,
                            void* data) noexcept;

  Eigen::MatrixXd a;
  Eigen::VectorXd k;
  double n;
  Eigen::Index size;
  double a_norm;              // ‖A‖∞ (max absolute row sum), for the round-off level of gap
  Eigen::VectorXd self_coupling;  // c_p = A_pp·k_p

  Eigen::VectorXd q, delta, force, gap;
  Eigen::VectorXd coordinate;  // y of the last solution: the warm start
  double scale = 1.0;          // s, from ‖q‖∞
  int iterations = 0;
  bool has_previous = false;

  // Scratch, sized once.
  Eigen::VectorXd work_delta, work_force, work_gap, work_stiffness, work_slope, candidate, polished, rhs, step;
  std::vector<char> in_contact;
  std::array<char, 256> last_message{};

  // Declared in dependency order: destroyed in reverse, so KINSOL goes first and the context last.
  ContextPtr context;
  VectorPtr u, ones;
  VectorPtr rhs_view, step_view;  // N_Vector views of rhs and step (data owned by Eigen)
  MatrixPtr jac;
  LinearSolverPtr linear_solver;
  KinsolPtr kinsol;
};

NonlinearSpringContact::Impl::Impl(Eigen::MatrixXd structural, Eigen::VectorXd stiffness, double exponent,
                                   bool require_symmetric)
    : a(std::move(structural)), k(std::move(stiffness)), n(exponent), size(a.rows()) {
  if (a.cols() != size) {
    throw std::invalid_argument("NonlinearSpringContact: the structural compliance A must be square (got " +
                                std::to_string(a.rows()) + " × " + std::to_string(a.cols()) + ")");
  }
  if (!a.allFinite()) {
    throw std::invalid_argument("NonlinearSpringContact: the structural compliance A has non-finite entries");
  }
  const double a_max = size > 0 ? a.cwiseAbs().maxCoeff() : 0.0;
  if (require_symmetric && size > 0 && (a - a.transpose()).cwiseAbs().maxCoeff() > 1e-12 * a_max) {
    throw std::invalid_argument("NonlinearSpringContact: the structural compliance A is not symmetric");
  }
  if (!require_symmetric && size > 0 && a.diagonal().minCoeff() < 0.0) {
    throw std::invalid_argument("NonlinearSpringContact: the structural compliance A has a negative diagonal");
  }
  if (require_symmetric && size > 0 && a_max > 0.0) {
    // A non-PSD compliance loses uniqueness of the contact solution (and the P-matrix property
    // Newton relies on); round-off-level negative eigenvalues are tolerated.
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(a, Eigen::EigenvaluesOnly);
    const Eigen::VectorXd& lambda = eigen.eigenvalues();
    if (lambda(0) < -1e-10 * lambda.cwiseAbs().maxCoeff()) {
      throw std::invalid_argument("NonlinearSpringContact: the structural compliance A is not positive "
                                  "semi-definite (smallest eigenvalue " + std::to_string(lambda(0)) + ")");
    }
  }
  if (k.size() != size) {
    throw std::invalid_argument("NonlinearSpringContact: the stiffness vector has " + std::to_string(k.size()) +
                                " entries, expected one per contact point (" + std::to_string(size) + ")");
  }
  if (size > 0 && !(k.allFinite() && k.minCoeff() > 0.0)) {
    throw std::invalid_argument("NonlinearSpringContact: the spring stiffnesses k must be finite and > 0");
  }
  if (!(std::isfinite(n) && n >= 1.0)) {
    throw std::invalid_argument("NonlinearSpringContact: the spring exponent n must be finite and ≥ 1 (got " +
                                std::to_string(n) + ")");
  }
  a_norm = size > 0 ? a.cwiseAbs().rowwise().sum().maxCoeff() : 0.0;
  // Round-off may leave a PSD diagonal entry at −0: the coordinate needs c ≥ 0.
  self_coupling = a.diagonal().cwiseMax(0.0).cwiseProduct(k);

  q = delta = force = gap = coordinate = Eigen::VectorXd::Zero(size);
  work_delta = work_force = work_gap = work_stiffness = work_slope = Eigen::VectorXd::Zero(size);
  candidate = polished = rhs = step = Eigen::VectorXd::Zero(size);
  in_contact.assign(static_cast<std::size_t>(size), 0);
  if (size == 0) return;  // nothing to solve: no SUNDIALS objects

  const auto length = static_cast<sunindextype>(size);
  SUNContext raw_context = nullptr;
  check(SUNContext_Create(nullptr, &raw_context), "SUNContext_Create");
  context.reset(raw_context);
  u.reset(created(N_VNew_Serial(length, context.get()), "an N_Vector"));
  ones.reset(created(N_VNew_Serial(length, context.get()), "an N_Vector"));
  N_VConst(1.0, ones.get());  // Φ and x are already scaled: unit KINSOL scalings
  N_VConst(0.0, u.get());
  // The polish reuses the dense matrix and LU of KINSOL (Eigen's blocked LU would allocate
  // workspace per call for large P); these views let it solve into Eigen vectors.
  rhs_view.reset(created(N_VMake_Serial(length, rhs.data(), context.get()), "an N_Vector"));
  step_view.reset(created(N_VMake_Serial(length, step.data(), context.get()), "an N_Vector"));
  jac.reset(created(SUNDenseMatrix(length, length, context.get()), "the dense Jacobian"));
  linear_solver.reset(created(SUNLinSol_Dense(u.get(), jac.get(), context.get()), "the dense linear solver"));
  kinsol.reset(created(KINCreate(context.get()), "the KINSOL solver"));
  void* mem = kinsol.get();
  check(KINSetErrHandlerFn(mem, &Impl::error_handler, this), "KINSetErrHandlerFn");
  check(KINInit(mem, &Impl::residual, u.get()), "KINInit");
  check(KINSetUserData(mem, this), "KINSetUserData");
  check(KINSetLinearSolver(mem, linear_solver.get(), jac.get()), "KINSetLinearSolver");
  check(KINSetJacFn(mem, &Impl::jacobian), "KINSetJacFn");
  check(KINSetFuncNormTol(mem, kFuncTol), "KINSetFuncNormTol");
  check(KINSetScaledStepTol(mem, kStepTol), "KINSetScaledStepTol");
  // A fresh Jacobian every iteration: it changes with the contact set, and a stale one costs
  // more iterations than the O(P³) factorisation it saves.
  check(KINSetMaxSetupCalls(mem, 1), "KINSetMaxSetupCalls");
  check(KINSetNumMaxIters(mem, kMaxIterations), "KINSetNumMaxIters");
  check(KINSetMaxNewtonStep(mem, kMaxNewtonStep), "KINSetMaxNewtonStep");
}

double NonlinearSpringContact::Impl::compression_of(double y, Eigen::Index p) const {
  const double t = std::abs(y);
  const double c = self_coupling(p);
  double d = t;
  if (t == 0.0 || c == 0.0) {
    d = t;
  } else if (n == 1.0) {
    d = t / (1.0 + c);
  } else if (n == 2.0) {
    d = 2.0 * t / (1.0 + std::sqrt(1.0 + 4.0 * c * t));  // the root of cδ² + δ = t, no cancellation
  } else {
    // g(δ) = δ + cδⁿ − t is increasing and convex, and min(t, (t/c)^{1/n}) bounds its root from
    // above within a factor 2: Newton from there decreases monotonically onto the root.
    d = std::min(t, std::pow(t / c, 1.0 / n));
    for (int i = 0; i < 100; ++i) {
      const double lower = std::pow(d, n - 1.0);
      const double g = d + c * lower * d - t;
      if (!(g > 0.0)) break;
      const double change = g / (1.0 + c * n * lower);
      d -= change;
      if (change <= kEps * d) break;
    }
  }
  return std::copysign(d, y);
}

void NonlinearSpringContact::Impl::evaluate_delta() {
  for (Eigen::Index p = 0; p < size; ++p) {
    const double d = work_delta(p);
    const double magnitude = std::abs(d);
    double power = magnitude;  // |δ|ⁿ
    double slope = 1.0;        // n|δ|^{n−1}
    if (n == 2.0) {
      power = magnitude * magnitude;
      slope = 2.0 * magnitude;
    } else if (n != 1.0) {
      const double lower = std::pow(magnitude, n - 1.0);
      power = lower * magnitude;
      slope = n * lower;
    }
    work_force(p) = k(p) * std::copysign(power, d);
    work_stiffness(p) = k(p) * slope;
  }
  work_gap.noalias() = a * work_force;
  work_gap += q + work_delta;
}

void NonlinearSpringContact::Impl::evaluate_coordinate(const Eigen::Ref<const Eigen::VectorXd>& y) {
  for (Eigen::Index p = 0; p < size; ++p) work_delta(p) = compression_of(y(p), p);
  evaluate_delta();
  for (Eigen::Index p = 0; p < size; ++p) work_slope(p) = 1.0 / (1.0 + std::max(a(p, p), 0.0) * work_stiffness(p));
}

double NonlinearSpringContact::Impl::merit(const Eigen::Ref<const Eigen::VectorXd>& first) const {
  double worst = 0.0;
  for (Eigen::Index p = 0; p < size; ++p) {
    const double phi = fischer_burmeister(first(p) / scale, work_gap(p) / scale);
    if (!std::isfinite(phi)) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, std::abs(phi));
  }
  return worst;
}

int NonlinearSpringContact::Impl::residual(N_Vector u_in, N_Vector f, void* data) noexcept {
  Impl& self = *static_cast<Impl*>(data);
  const Eigen::Map<const Eigen::VectorXd> x(N_VGetArrayPointer(u_in), self.size);
  Eigen::Map<Eigen::VectorXd> phi(N_VGetArrayPointer(f), self.size);
  self.candidate = self.scale * x;  // y
  self.evaluate_coordinate(self.candidate);
  for (Eigen::Index p = 0; p < self.size; ++p) phi(p) = fischer_burmeister(x(p), self.work_gap(p) / self.scale);
  // Overflow of δⁿ far from the solution: a recoverable error makes the line search back off.
  return phi.allFinite() ? 0 : 1;
}

int NonlinearSpringContact::Impl::jacobian(N_Vector u_in, N_Vector, SUNMatrix j, void* data, N_Vector,
                                           N_Vector) noexcept {
  Impl& self = *static_cast<Impl*>(data);
  const Eigen::Index points = self.size;
  const Eigen::Map<const Eigen::VectorXd> x(N_VGetArrayPointer(u_in), points);
  // Recomputed at u rather than cached: the last residual call may have been at a line-search
  // trial point. O(P²) against the O(P³) factorisation that follows.
  self.candidate = self.scale * x;
  self.evaluate_coordinate(self.candidate);
  // SUNDIALS dense matrices are column-major and contiguous.
  Eigen::Map<Eigen::MatrixXd> jm(SUNDenseMatrix_Data(j), points, points);
  // α and β are kept in rhs and step (free while KINSOL runs).
  Eigen::VectorXd& alpha = self.rhs;
  Eigen::VectorXd& beta = self.step;
  for (Eigen::Index p = 0; p < points; ++p) {
    const double a_p = x(p);
    const double b_p = self.work_gap(p) / self.scale;
    const double r = std::hypot(a_p, b_p);
    if (r > 0.0) {
      alpha(p) = 1.0 - a_p / r;
      beta(p) = 1.0 - b_p / r;
    } else {
      // The kink a = b = 0: the limit of ∇φ along (a, b) = t(1, 1), t → 0⁺.
      alpha(p) = beta(p) = 1.0 - 1.0 / std::sqrt(2.0);
    }
  }
  // ∂b/∂x = ∂gap/∂y = A·diag(dF/dy) + diag(dδ/dy), dF/dy = D·dδ/dy.
  for (Eigen::Index c = 0; c < points; ++c) {
    const double force_slope = self.work_stiffness(c) * self.work_slope(c);
    for (Eigen::Index i = 0; i < points; ++i) jm(i, c) = beta(i) * self.a(i, c) * force_slope;
    jm(c, c) += alpha(c) + beta(c) * self.work_slope(c);
  }
  return jm.allFinite() ? 0 : 1;
}

void NonlinearSpringContact::Impl::error_handler(int, const char* module, const char* function, char* message,
                                                 void* data) noexcept {
  // Failures are reported by the exception (after the retries), not printed by KINSOL; keep the
  // last message for it. Fixed buffer: no allocation inside a C callback.
  Impl& self = *static_cast<Impl*>(data);
  std::snprintf(self.last_message.data(), self.last_message.size(), "%s:%s: %s", module ? module : "",
                function ? function : "", message ? message : "");
}

double NonlinearSpringContact::Impl::gap_noise() const {
  return kEps * (q.cwiseAbs().maxCoeff() + a_norm * work_force.cwiseAbs().maxCoeff() + work_delta.cwiseAbs().maxCoeff());
}

int NonlinearSpringContact::Impl::run_kinsol() {
  const int flag = KINSol(kinsol.get(), u.get(), KIN_LINESEARCH, ones.get(), ones.get());
  long count = 0;
  KINGetNumNonlinSolvIters(kinsol.get(), &count);
  iterations += static_cast<int>(count);
  // δ(y) of the last iterate (after a failure too: it may be converged to round-off).
  const Eigen::Map<const Eigen::VectorXd> x(N_VGetArrayPointer(u.get()), size);
  candidate = scale * x;
  evaluate_coordinate(candidate);
  candidate = work_delta;
  if (!candidate.allFinite()) return flag < 0 ? flag : KIN_SYSFUNC_FAIL;
  polish(candidate);
  if (flag == KIN_SUCCESS || flag == KIN_INITIAL_GUESS_OK) return flag;
  // Not converged by KINSOL's test: accept only at the round-off level of the problem.
  // (Judged with δ clipped at 0, as it will be reported.)
  work_delta = candidate.cwiseMax(0.0);
  evaluate_delta();
  const double accept = std::max(kFuncTol, kNoiseFactor * gap_noise() / scale);
  return merit(work_delta) <= accept ? KIN_SUCCESS : (flag < 0 ? flag : KIN_LINESEARCH_NONCONV);
}

void NonlinearSpringContact::Impl::polish(Eigen::VectorXd& point) {
  // Both candidates are judged as they would be reported, with δ clipped at 0: for stiff springs
  // clipping a δ_p of −1e-15·s moves the other gaps by A·k·δ_p, far more than 1e-15·s.
  work_delta = point.cwiseMax(0.0);
  evaluate_delta();
  const double merit_before = merit(work_delta);
  // The contact set of the KINSOL solution: in contact where δ > gap (a > b in φ).
  work_delta = point;
  evaluate_delta();
  for (Eigen::Index p = 0; p < size; ++p) in_contact[p] = work_delta(p) > work_gap(p) ? 1 : 0;
  polished = point;
  for (Eigen::Index p = 0; p < size; ++p)
    if (!in_contact[p]) polished(p) = 0.0;
  auto contact_residual = [&]() {
    double worst = 0.0;
    for (Eigen::Index p = 0; p < size; ++p)
      if (in_contact[p]) worst = std::max(worst, std::abs(work_gap(p)));
    return worst;
  };
  work_delta = polished;
  evaluate_delta();
  double residual_now = contact_residual();
  for (int s = 0; s < kMaxPolishSteps; ++s) {
    // At the round-off level of gap = q + A·F + δ further steps only chase noise.
    if (!(residual_now > 4.0 * gap_noise())) break;
    // Rows in contact: ∂gap/∂δ = I + A·D; rows out of contact: the equation δ_p = 0. Its
    // determinant is a principal minor of the P-matrix I + A·D, so it is nonsingular. KINSOL's
    // matrix and LU are free here: every KINSol call starts with a fresh Jacobian and setup.
    Eigen::Map<Eigen::MatrixXd> newton(SUNDenseMatrix_Data(jac.get()), size, size);
    for (Eigen::Index c = 0; c < size; ++c) {
      const double d_c = work_stiffness(c);
      for (Eigen::Index i = 0; i < size; ++i) newton(i, c) = in_contact[i] ? a(i, c) * d_c : 0.0;
      newton(c, c) += 1.0;
    }
    for (Eigen::Index p = 0; p < size; ++p) rhs(p) = in_contact[p] ? work_gap(p) : 0.0;
    if (SUNLinSolSetup(linear_solver.get(), jac.get()) != 0) break;  // singular pivot: keep KINSOL's
    if (SUNLinSolSolve(linear_solver.get(), jac.get(), step_view.get(), rhs_view.get(), 0.0) != 0) break;
    ++iterations;
    work_delta = polished - step;
    evaluate_delta();
    const double residual_next = contact_residual();
    if (!(residual_next < residual_now)) break;  // no progress: keep the previous iterate
    polished = work_delta;
    residual_now = residual_next;
  }
  work_delta = polished.cwiseMax(0.0);
  evaluate_delta();
  if (merit(work_delta) <= merit_before) point = polished;
}

NonlinearSpringContact::NonlinearSpringContact(Eigen::MatrixXd structural, Eigen::VectorXd stiffness,
                                               double exponent, bool require_symmetric)
    : impl_(std::make_unique<Impl>(std::move(structural), std::move(stiffness), exponent, require_symmetric)) {}

NonlinearSpringContact::~NonlinearSpringContact() = default;

void NonlinearSpringContact::warm_start(const Eigen::Ref<const Eigen::VectorXd>& compression) {
  Impl& m = *impl_;
  if (compression.size() != m.size || !compression.allFinite())
    throw std::invalid_argument("NonlinearSpringContact::warm_start: " + std::to_string(m.size) + " finite compressions expected");
  // y = δ + A_pp·F(δ), F = k·δⁿ (the solver's coordinate).
  const Eigen::VectorXd delta = compression.cwiseMax(0.0);
  const Eigen::VectorXd force = m.k.cwiseProduct(delta.array().pow(m.n).matrix());
  m.coordinate = delta + m.a.diagonal().cwiseMax(0.0).cwiseProduct(force);
  m.has_previous = true;
}

const Eigen::VectorXd& NonlinearSpringContact::solve(const Eigen::Ref<const Eigen::VectorXd>& q) {
  Impl& m = *impl_;
  if (q.size() != m.size) {
    throw std::invalid_argument("NonlinearSpringContact::solve: q has " + std::to_string(q.size()) +
                                " entries, expected " + std::to_string(m.size));
  }
  if (!q.allFinite()) throw std::invalid_argument("NonlinearSpringContact::solve: q has non-finite entries");
  m.q = q;
  m.iterations = 0;
  const double scale = m.size > 0 ? q.cwiseAbs().maxCoeff() : 0.0;
  if (scale == 0.0) {
    // q = 0: δ = 0 gives gap = 0, which is complementary (and the solution is unique).
    m.delta.setZero();
    m.force.setZero();
    m.coordinate.setZero();
    m.gap = m.q;
    m.has_previous = true;
    return m.force;
  }
  m.scale = scale;

  // Starting points: the previous solution, then δ = 0, then the rigid-structure guess
  // δ = max(−q, 0) (exact for A = 0), in the coordinate y = δ + A_pp·F(δ).
  Eigen::Map<Eigen::VectorXd> x(N_VGetArrayPointer(m.u.get()), m.size);
  int flag = KIN_SUCCESS;
  bool solved = false;
  for (int attempt = 0; attempt < 3 && !solved; ++attempt) {
    if (attempt == 0) {
      if (!m.has_previous) continue;
      x = m.coordinate / scale;
    } else if (attempt == 1) {
      x.setZero();
    } else {
      m.work_delta = (-m.q).cwiseMax(0.0);
      m.evaluate_delta();
      x = (m.work_delta + m.a.diagonal().cwiseMax(0.0).cwiseProduct(m.work_force)) / scale;
    }
    m.last_message[0] = '\0';
    flag = m.run_kinsol();
    solved = flag >= 0;
  }
  if (!solved) {
    std::string text = "NonlinearSpringContact: KINSOL did not converge (flag " + flag_name(flag) + " = " +
                       std::to_string(flag) + ") from the warm start, δ = 0 or δ = max(−q, 0)";
    if (m.last_message[0] != '\0') text += "; " + std::string(m.last_message.data());
    throw std::runtime_error(text);
  }

  // Reported state: δ ≥ 0 (the solution can sit at −round-off), F and gap consistent with it.
  m.delta = m.candidate.cwiseMax(0.0);
  m.work_delta = m.delta;
  m.evaluate_delta();
  m.force = m.work_force;
  m.gap = m.work_gap;
  m.coordinate = m.delta + m.a.diagonal().cwiseMax(0.0).cwiseProduct(m.force);
  m.has_previous = true;
  return m.force;
}

const Eigen::VectorXd& NonlinearSpringContact::force() const noexcept { return impl_->force; }
const Eigen::VectorXd& NonlinearSpringContact::compression() const noexcept { return impl_->delta; }
const Eigen::VectorXd& NonlinearSpringContact::gap() const noexcept { return impl_->gap; }
int NonlinearSpringContact::iterations() const noexcept { return impl_->iterations; }

}  // namespace rollnoise
