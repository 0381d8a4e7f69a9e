#include "reference/cvode_reference.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/LU>

#include "contact/static_contact.hpp"
#include "road/road_profile.hpp"

namespace rollnoise::reference {

SdofModel make_model(const LumpedSystem& system) {
  if (system.points == 1) return SdofModel(system.parameters);
  if (system.points == 2) return SdofModel(system.parameters, system.coupling, system.spacing);
  throw std::invalid_argument("lumped reference: 1 or 2 points");
}

namespace {

// ---- RAII for the SUNDIALS C objects: each owner frees its object exactly once. ----------
struct ContextFree {
  void operator()(SUNContext context) const noexcept { SUNContext_Free(&context); }
};
struct VectorFree {
  void operator()(N_Vector vector) const noexcept { N_VDestroy(vector); }
};
struct MatrixFree {
  void operator()(SUNMatrix matrix) const noexcept { SUNMatDestroy(matrix); }
};
struct SolverFree {
  void operator()(SUNLinearSolver solver) const noexcept { SUNLinSolFree(solver); }
};
struct CvodeFree {
  void operator()(void* memory) const noexcept { CVodeFree(&memory); }
};
using ContextPtr = std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextFree>;
using VectorPtr = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorFree>;
using MatrixPtr = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixFree>;
using SolverPtr = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, SolverFree>;
using CvodePtr = std::unique_ptr<void, CvodeFree>;

void check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string("CVODE reference: ") + call + " failed (flag " +
                                         std::to_string(flag) + ")");
}
template <class T>
T checked(T pointer, const char* call) {
  if (pointer == nullptr) throw std::runtime_error(std::string("CVODE reference: ") + call + " failed");
  return pointer;
}

// ---- The lumped system's algebra, free of SUNDIALS. ------------------------------------------
// A mode is a bit mask of the points in contact (bit i: point i active).
class LumpedContact {
 public:
  LumpedContact(const LumpedSystem& system, const Eigen::MatrixXd& coupling, const RoadProfile& road,
                double speed, double indentation)
      : p_(system.parameters),
        n_(coupling.rows()),
        m_(coupling),
        road_(road),
        speed_(speed),
        d_(indentation),
        offsets_(static_cast<std::size_t>(n_), 0.0) {
    if (n_ > 1) offsets_[1] = system.spacing;
    // K_mode: F = −K_mode·q on that mode, with K_AA = (M_AA/s)⁻¹ and zeros elsewhere.
    const unsigned modes = 1u << n_;
    gain_.resize(modes);
    for (unsigned mode = 0; mode < modes; ++mode) {
      std::vector<Eigen::Index> active;
      for (Eigen::Index i = 0; i < n_; ++i)
        if (is_active(mode, i)) active.push_back(i);
      const auto a = static_cast<Eigen::Index>(active.size());
      Eigen::MatrixXd maa(a, a);
      for (Eigen::Index i = 0; i < a; ++i)
        for (Eigen::Index j = 0; j < a; ++j) maa(i, j) = m_(active[i], active[j]) / p_.contact_stiffness;
      const Eigen::MatrixXd inverse = a > 0 ? Eigen::MatrixXd(maa.inverse()) : Eigen::MatrixXd(0, 0);
      gain_[mode] = Eigen::MatrixXd::Zero(n_, n_);
      for (Eigen::Index i = 0; i < a; ++i)
        for (Eigen::Index j = 0; j < a; ++j) gain_[mode](active[i], active[j]) = inverse(i, j);
    }
  }

  static bool is_active(unsigned mode, Eigen::Index i) { return ((mode >> i) & 1u) != 0; }
  Eigen::Index points() const { return n_; }
  const SdofParameters& parameters() const { return p_; }

  Eigen::VectorXd road(double t) const {
    Eigen::VectorXd r(n_);
    for (Eigen::Index i = 0; i < n_; ++i) r(i) = road_.height(speed_ * t - offsets_[static_cast<std::size_t>(i)]);
    return r;
  }
  // Times at which the road under a point leaves its flat lead-in (x − offset_i = 0): the
  // slope of r_i jumps there, so the integration restarts there.
  std::vector<double> kinks() const {
    std::vector<double> times;
    for (double offset : offsets_) times.push_back(offset / speed_);
    return times;
  }
  // q = gap at F = 0: −d + M y − r (MODEL.md §2 with h = 0, u⁰ ↦ M y).
  Eigen::VectorXd free_gap(double t, const Eigen::Ref<const Eigen::VectorXd>& y) const {
    return (m_ * y).array() - d_ - road(t).array();
  }
  Eigen::VectorXd force(unsigned mode, const Eigen::VectorXd& q) const { return -gain_[mode] * q; }
  Eigen::VectorXd gap(const Eigen::VectorXd& force, const Eigen::VectorXd& q) const {
    return m_ * force / p_.contact_stiffness + q;
  }
  Eigen::VectorXd position(const Eigen::VectorXd& force, const Eigen::Ref<const Eigen::VectorXd>& y) const {
    return (m_ * (force / p_.contact_stiffness + y)).array() - d_;
  }

  // The LCP F ≥ 0, gap = (M/s)F + q ≥ 0, Fᵀgap = 0, by enumerating the 2ⁿ modes: for n ≤ 2
  // nothing is simpler, and it shares no code with the solver's active-set method. The unique
  // solution (M/s is SPD) has violation 0; round-off near a switch is resolved by taking the
  // least violation (gaps weighted by s, so both are forces).
  unsigned lcp_mode(const Eigen::VectorXd& q) const {
    unsigned best = 0;
    double best_violation = std::numeric_limits<double>::infinity();
    for (unsigned mode = 0; mode < gain_.size(); ++mode) {
      const Eigen::VectorXd f = force(mode, q);
      const Eigen::VectorXd g = gap(f, q);
      double violation = 0.0;
      for (Eigen::Index i = 0; i < n_; ++i) {
        violation = std::max(violation, is_active(mode, i) ? -f(i) : -p_.contact_stiffness * g(i));
      }
      if (violation < best_violation) {
        best = mode;
        best_violation = violation;
      }
    }
    return best;
  }

 private:
  SdofParameters p_;
  Eigen::Index n_;
  Eigen::MatrixXd m_;
  const RoadProfile& road_;
  double speed_;
  double d_;
  std::vector<double> offsets_;
  std::vector<Eigen::MatrixXd> gain_;
};

// What the CVODE callbacks see: the algebra and the mode being integrated.
struct Integration {
  const LumpedContact* contact;
  unsigned mode;
};

// State x = (y_1 … y_n, ẏ_1 … ẏ_n); m ÿ = F − r ẏ − k y with F from the current mode.
int right_hand_side(sunrealtype t, N_Vector x, N_Vector xdot, void* data) noexcept {
  try {
    const auto& run = *static_cast<const Integration*>(data);
    const LumpedContact& c = *run.contact;
    const Eigen::Index n = c.points();
    const Eigen::Map<const Eigen::VectorXd> state(N_VGetArrayPointer(x), 2 * n);
    Eigen::Map<Eigen::VectorXd> rate(N_VGetArrayPointer(xdot), 2 * n);
    const Eigen::VectorXd f = c.force(run.mode, c.free_gap(t, state.head(n)));
    const SdofParameters& p = c.parameters();
    rate.head(n) = state.tail(n);
    rate.tail(n) = (f - p.damping * state.tail(n) - p.stiffness * state.head(n)) / p.mass;
    return 0;
  } catch (...) {
    return -1;  // unrecoverable: CVode returns CV_RHSFUNC_FAIL
  }
}

// Root i: F_i while point i is in contact, gap_i while it is not.
int switching_functions(sunrealtype t, N_Vector x, sunrealtype* out, void* data) noexcept {
  try {
    const auto& run = *static_cast<const Integration*>(data);
    const LumpedContact& c = *run.contact;
    const Eigen::Index n = c.points();
    const Eigen::Map<const Eigen::VectorXd> state(N_VGetArrayPointer(x), 2 * n);
    const Eigen::VectorXd q = c.free_gap(t, state.head(n));
    const Eigen::VectorXd f = c.force(run.mode, q);
    const Eigen::VectorXd g = c.gap(f, q);
    for (Eigen::Index i = 0; i < n; ++i) out[i] = LumpedContact::is_active(run.mode, i) ? f(i) : g(i);
    return 0;
  } catch (...) {
    return -1;
  }
}

}  // namespace

CvodeReference simulate_cvode_reference(const LumpedSystem& system, const RoadProfile& road,
                                        double speed, double static_load,
                                        const Eigen::VectorXd& sample_times,
                                        const CvodeOptions& options) {
  if (sample_times.size() < 1) throw std::invalid_argument("CVODE reference: no sample times");
  if (!(speed > 0.0)) throw std::invalid_argument("CVODE reference: speed must be > 0");
  for (Eigen::Index j = 1; j < sample_times.size(); ++j)
    if (!(sample_times(j) > sample_times(j - 1))) throw std::invalid_argument("CVODE reference: sample times must increase");

  const SdofModel model = make_model(system);
  const Eigen::Index n = model.point_count();
  const SdofParameters& p = system.parameters;

  // Static equilibrium on the flat lead-in (MODEL.md §2, "Preload and start"): d from the
  // model's static compliance, each mass at rest at y_i = F_i/k.
  const StaticContact preload =
      solve_static_contact(model.static_compliance(), Eigen::VectorXd::Zero(n), static_load);
  const LumpedContact contact(system, model.coupling_matrix(), road, speed, preload.indentation);

  const double t0 = sample_times(0);
  const double t_final = sample_times(sample_times.size() - 1);
  const double contact_rate = std::sqrt((p.stiffness + p.contact_stiffness) / p.mass);
  // A hair after a switch: long enough that the forces and gaps that grow from 0 there are far
  // above the root's location error, short enough that y ≈ y + ε ẏ is exact to O(ε²).
  const double hair = 1e-6 / contact_rate;

  const double y_scale = options.displacement_scale > 0.0
                             ? options.displacement_scale
                             : (preload.force.maxCoeff() > 0.0 ? preload.force.maxCoeff() / p.stiffness : 1e-6);
  const double v_scale =
      options.velocity_scale > 0.0 ? options.velocity_scale : y_scale * std::sqrt(p.stiffness / p.mass);

  // SUNDIALS objects, declared so that they are destroyed in reverse order of dependence.
  SUNContext raw_context = nullptr;
  check(SUNContext_Create(nullptr, &raw_context), "SUNContext_Create");
  const ContextPtr context(raw_context);
  const auto length = static_cast<sunindextype>(2 * n);
  const VectorPtr x(checked(N_VNew_Serial(length, context.get()), "N_VNew_Serial"));
  const VectorPtr abstol(checked(N_VNew_Serial(length, context.get()), "N_VNew_Serial"));
  const MatrixPtr jacobian(checked(SUNDenseMatrix(length, length, context.get()), "SUNDenseMatrix"));
  const SolverPtr linear(checked(SUNLinSol_Dense(x.get(), jacobian.get(), context.get()), "SUNLinSol_Dense"));
  const CvodePtr cvode(checked(
      CVodeCreate(options.method == CvodeMethod::bdf ? CV_BDF : CV_ADAMS, context.get()), "CVodeCreate"));
  void* mem = cvode.get();

  Eigen::Map<Eigen::VectorXd> state(N_VGetArrayPointer(x.get()), 2 * n);
  state.head(n) = preload.force / p.stiffness;
  state.tail(n).setZero();
  Eigen::Map<Eigen::VectorXd> atol(N_VGetArrayPointer(abstol.get()), 2 * n);
  atol.head(n).setConstant(options.relative_tolerance * y_scale);
  atol.tail(n).setConstant(options.relative_tolerance * v_scale);

  // The mode that holds just after t: the LCP a hair later, on y extrapolated with ẏ.
  auto mode_after = [&](double t) {
    const Eigen::VectorXd y = state.head(n) + hair * state.tail(n);
    return contact.lcp_mode(contact.free_gap(t + hair, y));
  };
  Integration run{&contact, mode_after(t0)};

  check(CVodeInit(mem, right_hand_side, t0, x.get()), "CVodeInit");
  check(CVodeSetUserData(mem, &run), "CVodeSetUserData");
  check(CVodeSVtolerances(mem, options.relative_tolerance, abstol.get()), "CVodeSVtolerances");
  check(CVodeSetLinearSolver(mem, linear.get(), jacobian.get()), "CVodeSetLinearSolver");
  check(CVodeSetMaxNumSteps(mem, 1000000), "CVodeSetMaxNumSteps");
  // A step never spans a whole contact oscillation, so no switch pair hides inside one step.
  check(CVodeSetMaxStep(mem, 1.0 / contact_rate), "CVodeSetMaxStep");
  check(CVodeRootInit(mem, static_cast<int>(n), switching_functions), "CVodeRootInit");
  // Only a falling F_i (contact lost) or a falling gap_i (contact made) is a switch; just after
  // a switch the new function starts at ±round-off and rises, which must not count.
  std::vector<int> direction(static_cast<std::size_t>(n), -1);
  check(CVodeSetRootDirection(mem, direction.data()), "CVodeSetRootDirection");
  check(CVodeSetNoInactiveRootWarn(mem), "CVodeSetNoInactiveRootWarn");

  std::vector<double> stops;
  for (double kink : contact.kinks())
    if (kink > t0 && kink < t_final) stops.push_back(kink);
  stops.push_back(t_final);
  std::sort(stops.begin(), stops.end());

  CvodeReference result;
  const Eigen::Index samples = sample_times.size();
  result.time = sample_times;
  result.displacement.resize(samples, n);
  result.force.resize(samples, n);
  result.road.resize(samples, n);
  result.indentation = preload.indentation;
  result.preload_force = preload.force;

  long steps_before_restarts = 0;
  auto restart = [&](double t) {
    long steps = 0;
    check(CVodeGetNumSteps(mem, &steps), "CVodeGetNumSteps");
    steps_before_restarts += steps;
    check(CVodeReInit(mem, t, x.get()), "CVodeReInit");
  };

  double t = t0;
  std::vector<int> found(static_cast<std::size_t>(n));
  for (Eigen::Index j = 0; j < samples; ++j) {
    const double tout = sample_times(j);
    while (t < tout) {
      const double stop = *std::upper_bound(stops.begin(), stops.end(), t);
      check(CVodeSetStopTime(mem, stop), "CVodeSetStopTime");
      sunrealtype reached = t;
      const int flag = CVode(mem, tout, x.get(), &reached, CV_NORMAL);
      check(flag, "CVode");
      t = reached;
      if (flag == CV_ROOT_RETURN) {
        check(CVodeGetRootInfo(mem, found.data()), "CVodeGetRootInfo");
        unsigned flipped = run.mode;
        for (Eigen::Index i = 0; i < n; ++i)
          if (found[static_cast<std::size_t>(i)] != 0) flipped ^= 1u << i;
        // For one point the flip is always right; with coupling the rates of the others may
        // decide otherwise (an LCP in the rates), which the LCP a hair later settles.
        run.mode = mode_after(t);
        if (run.mode != flipped) ++result.mode_corrections;
        ++result.contact_switches;
        restart(t);
      } else if (flag == CV_TSTOP_RETURN) {
        run.mode = mode_after(t);
        if (t < t_final) restart(t);
      }
    }
    const Eigen::VectorXd y = state.head(n);
    const Eigen::VectorXd q = contact.free_gap(tout, y);
    const Eigen::VectorXd f = contact.force(contact.lcp_mode(q), q);
    result.force.row(j) = f.transpose();
    result.displacement.row(j) = contact.position(f, y).transpose();
    result.road.row(j) = contact.road(tout).transpose();
  }
  long steps = 0;
  check(CVodeGetNumSteps(mem, &steps), "CVodeGetNumSteps");
  result.cvode_steps = steps_before_restarts + steps;
  return result;
}

}  // namespace rollnoise::reference
