#pragma once
// The rolling tyre (MODEL.md §4): any translation-invariant tyre model (rolling_modes.hpp: the
// Kropp plate with a local tread compliance, or a model that includes its tread), rolling at
// constant speed over a road, one exact contact problem per step over the fixed contact window.
//
// The axle height is fixed by steady rolling on a smooth road: the steady force F_s solves the
// LCP with the compliance summed over all lags (non-symmetric when damped), and the
// indentation d is the one for which ΣF_s = W. The run starts from that steady state (its
// pre-history is part of u⁰), so a smooth road keeps F_s exactly and outputs have no start-up
// transient.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "contact/air_pumping.hpp"
#include "contact/contact_matrix_structure.hpp"
#include "contact/history_engine.hpp"
#include "contact/rolling_modes.hpp"
#include "contact/texture_contact_laws.hpp"
#include "contact/tread_pattern.hpp"

namespace rollnoise {

class RoadSurface;
class ProgressReporter;

// How the window's points read a road whose texture is finer than the cells (issue 10 §3). The
// points are dx apart, so texture shorter than 2·dx aliases across the window: its components at
// the cell's wavenumber 2π/dx and its harmonics modulate the contact at the cell-passing
// frequency v/dx (hidden at p = 1, where it aliases to 0 Hz, but the Nyquist frequency for p = 2
// sub-steps), and the rest (λ between dx and 2·dx) reaches the total force as a long wave that
// the patch does not average out.
//  - point: r(x) (before issue 10 §3);
//  - cell_mean: the mean over [x − dx/2, x + dx/2] (midpoint rule, 8 samples): removes the
//    components at 2π/dx and its harmonics; gain sinc(π·dx/λ): −0.4 dB at λ = 5·dx, −3.9 dB at
//    2·dx, −18 dB at 1.13·dx;
//  - lowpass (default): a Lanczos-windowed sinc (3 lobes, cut-off at λ = 2·dx, 4 samples per
//    cell over ±3 cells, unit gain at λ → ∞): −1.4 dB at λ = 2.56·dx, −0.7 dB at 2.84·dx, 0 from
//    3.6·dx; −6 dB at 2·dx; −26 dB at 1.5·dx, −40 to −57 dB from 1.42·dx to dx. What the points
//    cannot resolve is removed instead of aliased.
// Neither removes the modulation at v/dx that the contact's own nonlinearity makes as texture
// features pass the fixed points (docs/physics/contact.md, "The band up to 5 kHz").
enum class RoadSampling { point, cell_mean, lowpass };

// How a contact cell meets the road's texture inside it.
//  - rigid: as a flat punch on the road height RoadSampling gives (the cells of before);
//  - texture: each cell meets the road at its highest point and adds, in series with the tyre,
//    the per-cell law of the rubber pressed onto the texture inside it (cell_contact_law.hpp,
//    texture_contact_laws.hpp), solved each step by Newton over contact sets.
enum class ContactLaw { rigid, texture };

// When the skew part of G0, taken one step late, would multiply a perturbation of the forces by
// more than this per step (TyreContactTrace::lagged_skew_growth), each step solves the LCP with
// the whole, non-symmetric G0 instead (rolling_tyre.cpp). The estimate leaves out the coupling
// through the later lags, so it errs low: the passenger two-layer tyre at 80 km/h estimates 0.72
// and with the lag a round-off perturbation grew about ×2.8 per step; the passenger plate
// estimates 0.017 and stays steady to round-off. Hence a margin of 10 × below 1.
inline constexpr double whole_contact_matrix_above = 0.1;

struct TyreRunSettings {
  double speed = 0.0;        // v, m/s (Δt = dx/(p·v))
  double duration = 0.0;     // s
  double static_load = 0.0;  // W, N
  HistoryKind history = HistoryKind::automatic;
  // The road height a contact point meets (RoadSampling): the road low-passed along x at the
  // wavelength 2·dx that the window's points resolve, the mean over its cell's length along the
  // road [x − dx/2, x + dx/2], or the point value r(x).
  RoadSampling road_sampling = RoadSampling::lowpass;
  // Whether the trace keeps the window fields of every step (force, displacement, road:
  // samples × points each). A run that streams them through a ContactStepSink does not, so its
  // memory does not grow with its length.
  bool keep_fields = true;
  ContactLaw contact_law = ContactLaw::rigid;
  TreadRubber rubber = {};  // the texture law's rubber (E at the contact's time scale, ν)
  int law_threads = 1;  // threads that compute the laws before the run
  std::optional<std::filesystem::path> law_cache = {};  // where the laws are kept between runs (none: not kept)
  // The tread pattern (tread_pattern.hpp), rotating with the tread through the window; none: a
  // slick, and the run is exactly that of before. Not with the texture law.
  std::shared_ptr<const TreadPattern> pattern = nullptr;
  // Whether each step also follows the air in the patch (air_pumping.hpp) into
  // TyreContactTrace::air_pumping; off, the run is exactly that of before.
  bool air_pumping = false;
};

struct TyreContactTrace {
  Eigen::VectorXd time;            // s
  Eigen::MatrixXd force;           // N, samples × P (p = i + Nw·j)
  Eigen::MatrixXd displacement;    // vertical position of the tread surface, road datum, m
  Eigen::MatrixXd road;            // m
  Eigen::VectorXd total_force;     // N
  Eigen::VectorXd contact_area;    // m²
  Eigen::VectorXd contact_length;  // m, extent along x of the points in contact
  Eigen::VectorXd contact_width;   // m, extent across
  Eigen::VectorXd input_power;     // W, power of the contact forces into the tyre, Σ F·u̇
  std::vector<int> lcp_iterations;  // pivoting iterations per step (Newton iterations for a nonlinear tread)
  std::vector<int> state_changes;   // points that changed state against the step's warm start (not for KINSOL)
  ContactMatrixStructure contact_matrix;  // of G0, measured on the steady contact
  // Largest entry of the skew part of G0 over the largest of G0.
  double contact_matrix_skewness = 0.0;
  // Whether that skew part was taken one step late (at the previous step's force; G0 skewed by
  // at most whole_contact_matrix_above) or the whole G0 solved at each step.
  bool skew_part_lagged = true;
  // The factor per step by which the lag would multiply a perturbation (estimated at the steady
  // active set): the spectral radius of S_AA⁻¹K_AA.
  double lagged_skew_growth = 0.0;
  double indentation = 0.0;        // d, m
  Eigen::VectorXd steady_force;    // F_s, N
  Eigen::VectorXd steady_displacement;  // tread surface position in steady rolling, m
  double steady_rolling_resistance = 0.0;  // N, from F_s and the steady deformation
  std::string engine;
  std::vector<std::string> warnings;
  double step_loop_seconds = 0.0;  // wall time of the time-step loop alone (no setup)
  double history_seconds = 0.0;    // of which in the history engine (u⁰ and the update)
  double lcp_seconds = 0.0;        // of which in the contact problem of each step (LCP or nonlinear)
  double sink_seconds = 0.0;       // in the ContactStepSink, not counted in step_loop_seconds
  long lcp_factorisations = -1;    // dense factorisations of the LCP's basic block (−1: a nonlinear tread)
  long lcp_cg_iterations = 0;      // conjugate-gradient iterations (a well-conditioned symmetric step)
  // The texture contact law (ContactLaw::texture): its cells, each cell's pixels, the wall time
  // of computing them, and the largest cell force of the run against the laws' table end.
  std::size_t law_cells = 0;
  CellPixels law_pixels = {};
  double law_seconds = 0.0;
  bool laws_from_cache = false;
  double law_force_cap = 0.0;
  double largest_cell_force = 0.0;
  // The air pumped out of the patch (TyreRunSettings::air_pumping; empty without it).
  AirPumpingTrace air_pumping;
};

// The steady rolling state on a smooth road under load W: indentation and forces.
struct SteadyRolling {
  double indentation = 0.0;
  Eigen::VectorXd force;
  Eigen::VectorXd deformation;   // tyre surface displacement u (structure + tread), m
  Eigen::VectorXd displacement;  // tread surface position h − d + u, m
  double rolling_resistance = 0.0;  // N: the work of the contact forces on u per metre rolled
};
// A nonlinear tread (MODEL.md §4): springs F_p = k_p·δ_p^n in series with the belt, instead of a
// linear local compliance (which must then be zero).
// The steady state and each step are solved by Newton over contact sets with FFT products
// (tread_newton_contact.hpp); the KINSOL solver of the candidate points
// (nonlinear_tread_contact.hpp) is the reference that the tests compare it with.
enum class NonlinearTreadSolver { newton, kinsol };
struct NonlinearTread {
  Eigen::VectorXd stiffness;  // k_p, N/m^n per window point
  double exponent = 1.0;      // n ≥ 1
  NonlinearTreadSolver solver = NonlinearTreadSolver::newton;
};

// One step of a rolling run as the loop produces it, over the window (p = i + Nw·j).
struct ContactStep {
  std::size_t index = 0;
  double time = 0.0;                    // s
  const Eigen::VectorXd& force;         // N
  const Eigen::VectorXd& displacement;  // tread surface position, road datum, m
  const Eigen::VectorXd& road;          // m
};

// Takes each step as the contact loop produces it (the response stage and the streamed outputs
// of a run), so that the run need not hold its fields (issue 13: memory flat with run length).
class ContactStepSink {
 public:
  virtual ~ContactStepSink() = default;
  // Once, before the first step: the steady rolling state the run starts from.
  virtual void start(const SteadyRolling& steady) = 0;
  virtual void take(const ContactStep& step) = 0;
};

SteadyRolling solve_steady_rolling(const RollingModes& modes, const Eigen::MatrixXd& local_compliance,
                                   double load, const NonlinearTread* nonlinear = nullptr);

TyreContactTrace simulate_rolling_tyre(const RollingModes& modes, const Eigen::MatrixXd& local_compliance,
                                       const RoadSurface& road, const TyreRunSettings& settings,
                                       ProgressReporter* progress = nullptr,
                                       const NonlinearTread* nonlinear = nullptr, ContactStepSink* sink = nullptr);

}  // namespace rollnoise
