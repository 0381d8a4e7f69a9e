#pragma once
// An independent reference for the Green's-function contact solver (simulate_point_contact):
// the paper's §4 point models (MODEL.md §3) integrated as the lumped ODE system they stand for,
// with SUNDIALS CVODE and root finding at every contact switch.
//
// The lumped system, n = 1 (sdof) or 2 (coupled_sdof, coupling matrix M = [[1,c],[c,1]]):
//   m ÿ_i + r ẏ_i + k y_i = F_i                      (frame fixed; h of MODEL.md §3)
//   p_i = −d + Σ_j M_ij (F_j/s + y_j)                 (u = M·(δ/s + h) * F, eq. 7)
//   r_i(t) = road.height(v t − offset_i),  offsets {0, spacing}
//   F ≥ 0,  gap = p − r ≥ 0,  Fᵀ·gap = 0              (the LCP of MODEL.md §2, continuous in t)
// Within a contact mode (active set A) F_A = (M_AA/s)⁻¹ (r_A + d − (M y)_A), F = 0 elsewhere:
// smooth in t, so CVODE integrates each mode to its tolerance; the mode changes at the roots
// of F_i (active points) and gap_i (inactive points).
#include <Eigen/Core>

#include "greens/sdof_model.hpp"

namespace rollnoise {

class RoadProfile;

namespace reference {

struct LumpedSystem {
  SdofParameters parameters;
  Eigen::Index points = 1;  // 1: sdof; 2: coupled_sdof
  double coupling = 0.0;    // c (points == 2)
  double spacing = 0.0;     // distance of the second point behind the first, m (points == 2)
};

// The Green's-function model of the same system (the solver's input).
SdofModel make_model(const LumpedSystem& system);

enum class CvodeMethod { bdf, adams };

struct CvodeOptions {
  double relative_tolerance = 1e-10;
  // Absolute tolerances are relative_tolerance times these scales; 0 picks them from the
  // problem: the static deflection W/k (or 1 µm without load) for y and that times √(k/m) for ẏ.
  double displacement_scale = 0.0;  // m
  double velocity_scale = 0.0;      // m/s
  // Adams by default: the system is not stiff (its fastest rate, the contact resonance
  // √((k+s)/m), is resolved by the steps the tolerance asks for anyway), and at equal rtol
  // Adams' global error is ~10× below BDF's here. BDF is the cross-check.
  CvodeMethod method = CvodeMethod::adams;
};

struct CvodeReference {
  Eigen::VectorXd time;          // the sample times, s
  Eigen::MatrixXd displacement;  // p_i (samples × points), m, same datum as the road
  Eigen::MatrixXd force;         // F_i (samples × points), N; exactly 0 out of contact
  Eigen::MatrixXd road;          // r_i (samples × points), m
  double indentation = 0.0;      // d, m
  Eigen::VectorXd preload_force; // static F_i under W on the flat road, N
  long contact_switches = 0;     // roots at which a point changed mode
  // Switches where the LCP a hair after the root chose another mode than flipping the point
  // that hit the root (a coupled switch); informational.
  long mode_corrections = 0;
  long cvode_steps = 0;
};

// Integrates from t = sample_times(0) (static equilibrium under `static_load` on the flat
// lead-in of the road, which must be 0 up to x = 0) and records p and F at every sample time
// (increasing). Throws std::runtime_error when CVODE fails.
CvodeReference simulate_cvode_reference(const LumpedSystem& system, const RoadProfile& road,
                                        double speed, double static_load,
                                        const Eigen::VectorXd& sample_times,
                                        const CvodeOptions& options = {});

}  // namespace reference
}  // namespace rollnoise
