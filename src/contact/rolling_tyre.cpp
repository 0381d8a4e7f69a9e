#include "contact/rolling_tyre.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include <Eigen/Cholesky>

#include "contact/direct_history_engine.hpp"
#include "contact/illinois_bracket.hpp"
#include "contact/modal_history_engine.hpp"
#include "contact/nonlinear_tread_contact.hpp"
#include "contact/pmatrix_lcp.hpp"
#include "contact/static_contact.hpp"
#include "contact/tread_newton_contact.hpp"
#include "contact/window_convolution.hpp"
#include "core/cancellation.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "road/road_surface.hpp"

namespace rollnoise {
namespace {

// Work of the contact forces on the tyre's deformation u (not its rigid geometry), per metre
// rolled. Material moves one cell towards −x per step: the material at window column i now was
// at column i + 1 a step before. Over that step a force doing work ∫F du is taken by the
// trapezoidal rule, ½(F_now + F_before)(u_now − u_before), which makes the elastic (lossless)
// parts add up to exactly zero. Points at the front edge have no neighbour ahead; their force is
// zero when the window is long enough (a warning says when it is not).
double power_per_metre(const TyreGrid& grid, const Eigen::VectorXd& force_now, const Eigen::VectorXd& u_now,
                       const Eigen::VectorXd& force_before, const Eigen::VectorXd& u_before) {
  double sum = 0.0;
  for (int j = 0; j < grid.lateral; ++j)
    for (int i = 0; i + 1 < grid.window; ++i) {
      const Eigen::Index p = i + static_cast<Eigen::Index>(grid.window) * j;
      sum += 0.5 * (force_now(p) + force_before(p + 1)) * (u_now(p) - u_before(p + 1));
    }
  return sum / grid.dx();
}

// With the skew part K of G0 taken at the previous step's force, the points in contact obey
// S·F(n) = −q(n) − K·F(n−1) (S the symmetric part), so a perturbation of the forces is
// multiplied each step by −S_AA⁻¹K_AA on the active set A. Its spectral radius, estimated on
// the steady active set by power iteration (the geometric mean of the growth over 60 steps
// after 20 to settle), says whether the lag is safe: well below 1, errors die out as fast as the
// step discretisation's own; near or above 1 they persist or grow.
double lagged_skew_growth(const Eigen::MatrixXd& symmetric, const Eigen::MatrixXd& skew, const Eigen::VectorXd& force) {
  std::vector<Eigen::Index> active;
  for (Eigen::Index p = 0; p < force.size(); ++p)
    if (force(p) > 0.0) active.push_back(p);
  if (active.empty()) return 0.0;
  const auto a = static_cast<Eigen::Index>(active.size());
  Eigen::MatrixXd s(a, a), k(a, a);
  for (Eigen::Index i = 0; i < a; ++i)
    for (Eigen::Index j = 0; j < a; ++j) {
      s(i, j) = symmetric(active[static_cast<std::size_t>(i)], active[static_cast<std::size_t>(j)]);
      k(i, j) = skew(active[static_cast<std::size_t>(i)], active[static_cast<std::size_t>(j)]);
    }
  const Eigen::LLT<Eigen::MatrixXd> factor(s);
  if (factor.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(a, 1.0, 2.0);  // deterministic, not special
  x.normalize();
  double log_growth = 0.0;
  for (int iteration = 0; iteration < 80; ++iteration) {
    x = factor.solve(k * x);
    const double norm = x.norm();
    if (!(norm > 0.0)) return 0.0;
    if (iteration >= 20) log_growth += std::log(norm);
    x /= norm;
  }
  return std::exp(log_growth / 60.0);
}

// The taps of RoadSampling along x: offsets (m) and weights summing to 1.
struct RoadFilter {
  std::vector<double> offsets;
  std::vector<double> weights;
};

RoadFilter make_road_filter(RoadSampling sampling, double dx) {
  RoadFilter f;
  switch (sampling) {
    case RoadSampling::point:
      f.offsets = {0.0};
      f.weights = {1.0};
      break;
    case RoadSampling::cell_mean:
      for (int s = 0; s < 8; ++s) {
        f.offsets.push_back((s + 0.5) * dx / 8.0 - 0.5 * dx);
        f.weights.push_back(1.0 / 8.0);
      }
      break;
    case RoadSampling::lowpass: {
      // The ideal low-pass at the wavenumber π/dx (λ = 2·dx), h(ξ) ∝ sinc(ξ/dx), under a
      // Lanczos window sinc(ξ/(3dx)) over |ξ| < 3dx, sampled at dx/4; unit gain at λ → ∞.
      const auto sinc = [](double z) { return z == 0.0 ? 1.0 : std::sin(M_PI * z) / (M_PI * z); };
      double total = 0.0;
      for (int s = -12; s <= 12; ++s) {
        const double xi = s * dx / 4.0;
        const double w = sinc(xi / dx) * sinc(xi / (3.0 * dx));
        f.offsets.push_back(xi);
        f.weights.push_back(w);
        total += w;
      }
      for (double& w : f.weights) w /= total;
      break;
    }
  }
  return f;
}

}  // namespace

namespace {

// Window point (i, j) → (i − 1, j); the last column's points leave.
std::vector<Eigen::Index> shift_along_window(const TyreGrid& grid) {
  std::vector<Eigen::Index> shift_back(static_cast<std::size_t>(grid.points()), -1);
  for (int j = 0; j < grid.lateral; ++j)
    for (int i = 1; i < grid.window; ++i) {
      const Eigen::Index p = i + static_cast<Eigen::Index>(grid.window) * j;
      shift_back[static_cast<std::size_t>(p)] = p - 1;
    }
  return shift_back;
}

// Steady rolling with the nonlinear tread: the indentation d with ΣF(d) = W, where F(d) solves
// the nonlinear complementarity problem with the steady-rolling compliance T. ΣF is continuous
// and increasing in d: regula falsi (Illinois) inside a bracket.
// Each solve starts from the last one's compressions. By TreadNewtonContact (BiCGSTAB: T is
// not symmetric; products by FFT when T depends on x_p − x_q only), or the KINSOL reference.
template <class Contact>
StaticContact steady_nonlinear_contact(Contact& contact, const Eigen::VectorXd& h, double load,
                                       Eigen::VectorXd& compression) {
  const double touch = h.minCoeff();
  Eigen::VectorXd q(h.size());
  auto excess = [&](double d) {
    q = (h.array() - d).matrix();
    contact.solve(q);
    return contact.force().sum() - load;
  };
  IllinoisBracket bracket = bracket_by_doubling(touch, -load, 1e-3, 1.0,
                                                "steady rolling: no indentation below 1 m carries the load", excess);
  for (int iteration = 0; iteration < 200 && std::abs(bracket.hi - bracket.lo) > 1e-15 * std::abs(bracket.hi);
       ++iteration) {
    const double d = bracket.regula_falsi();
    const double f = excess(d);
    if (std::abs(f) <= 1e-12 * load) {
      bracket.lo = bracket.hi = d;
      break;
    }
    bracket.narrow(d, f);
  }
  const double d = 0.5 * (bracket.lo + bracket.hi);
  excess(d);
  compression = contact.compression();
  return StaticContact{d, contact.force()};
}

// The texture laws of the cells the window's points meet over the run (positions m = 0 …
// positions − 1 at x(0) + m·dx/p, as the road ring reads them; cell m·Ny + j), computed or read
// from the cache; what it took goes into the trace.
std::shared_ptr<const CellContactLaws> texture_laws_of_run(const TyreGrid& grid, int substeps, std::size_t positions,
                                                           const RoadSurface& road, const TyreRunSettings& settings,
                                                           TyreContactTrace& trace) {
  const auto started = std::chrono::steady_clock::now();
  ContactCellGrid cells;
  cells.dx = grid.dx();
  cells.dy = grid.dy();
  cells.x0 = grid.x(0);
  cells.step = grid.dx() / substeps;
  cells.positions = positions;
  for (int j = 0; j < grid.lateral; ++j) cells.lines.push_back(grid.y(j) - 0.5 * grid.width);
  trace.law_pixels = cell_pixels(cells.dx, cells.dy, road.sample_spacing(), "", "[road] sample_spacing");
  const TextureLawCache cache{settings.law_cache, &trace.laws_from_cache, &trace.warnings};
  auto laws =
      make_texture_contact_laws(road, cells, trace.law_pixels, settings.rubber, settings.law_threads, nullptr, &cache);
  trace.law_cells = laws->cells();
  trace.law_force_cap = laws->force_cap();
  trace.law_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return laws;
}

}  // namespace

SteadyRolling solve_steady_rolling(const RollingModes& modes, const Eigen::MatrixXd& local_compliance,
                                   double load, const NonlinearTread* nonlinear) {
  const TyreGrid& grid = modes.grid();
  const Eigen::MatrixXd compliance = local_compliance + modes.rolling_compliance();
  const Eigen::VectorXd h = grid.undeformed_gap();
  Eigen::VectorXd compression = Eigen::VectorXd::Zero(h.size());
  std::optional<StaticContact> solved;
  if (!nonlinear) {
    solved = solve_static_contact(compliance, h, load);
  } else if (nonlinear->solver == NonlinearTreadSolver::kinsol) {
    NonlinearTreadContact springs(compliance, nonlinear->stiffness, nonlinear->exponent, /*require_symmetric=*/false);
    solved = steady_nonlinear_contact(springs, h, load, compression);
  } else {
    std::optional<ContactWindow> window;
    if (matrix_unchanged_by(compliance, shift_along_window(grid))) window = ContactWindow{grid.window, grid.lateral};
    TreadNewtonContact springs(compliance, nonlinear->stiffness, nonlinear->exponent, window,
                               /*require_symmetric=*/false);
    solved = steady_nonlinear_contact(springs, h, load, compression);
  }
  const StaticContact& contact = *solved;
  SteadyRolling steady;
  steady.indentation = contact.indentation;
  steady.force = contact.force;
  steady.deformation = compliance * contact.force + compression;
  const Eigen::VectorXd& deformation = steady.deformation;
  steady.displacement = (h.array() - contact.indentation).matrix() + deformation;
  // In steady rolling the material at point p came from point p + 1 one step before, in the
  // same steady shape.
  steady.rolling_resistance = power_per_metre(grid, steady.force, deformation, steady.force, deformation);
  return steady;
}

TyreContactTrace simulate_rolling_tyre(const RollingModes& modes, const Eigen::MatrixXd& local_compliance,
                                       const RoadSurface& road, const TyreRunSettings& settings,
                                       ProgressReporter* progress, const NonlinearTread* nonlinear,
                                       ContactStepSink* sink) {
  const TyreGrid& grid = modes.grid();
  const Eigen::Index points = grid.points();
  const double dt = modes.time_step();
  const int substeps = modes.substeps();
  if (std::abs(dt * substeps * settings.speed - grid.dx()) > 1e-9 * grid.dx())
    throw std::invalid_argument("rolling tyre: the time step must be dx/(p·v), p the sub-steps per cell");
  const auto steps = static_cast<std::size_t>(std::llround(settings.duration / dt));
  const std::size_t samples = steps + 1;
  const RoadFilter road_filter = make_road_filter(settings.road_sampling, grid.dx());

  if (modes.tyre().includes_tread() && nonlinear)
    throw std::invalid_argument("rolling tyre: the " + modes.tyre().name() +
                                " model includes its tread's local deformation; a separate tread is not allowed");
  if (nonlinear && local_compliance.cwiseAbs().maxCoeff() > 0.0)
    throw std::invalid_argument("rolling tyre: a nonlinear tread has no linear local compliance");
  const bool texture_law = settings.contact_law == ContactLaw::texture;
  if (texture_law && nonlinear)
    throw std::invalid_argument("rolling tyre: the texture contact law and a nonlinear tread are alternatives");
  // A cell's texture law presses all of its rubber onto the road's texture; a cell partly over a
  // groove would need a law of its block's share, which the laws do not have.
  if (texture_law && settings.pattern)
    throw std::invalid_argument("rolling tyre: a tread pattern is not available with the texture contact law");
  const SteadyRolling steady = solve_steady_rolling(modes, local_compliance, settings.static_load, nonlinear);

  std::unique_ptr<HistoryEngine> engine;
  std::shared_ptr<const DiscreteKernel> kernel;
  Eigen::MatrixXd g0;
  if (settings.history == HistoryKind::direct) {
    auto dense = std::make_shared<DiscreteKernel>(modes.sheared_kernel(samples));
    dense->lags[0] += local_compliance;
    dense->total += local_compliance;
    kernel = dense;
    g0 = kernel->lags[0];
    engine = std::make_unique<DirectHistoryEngine>(kernel, samples, steady.force);
  } else if (settings.history == HistoryKind::modal || settings.history == HistoryKind::automatic) {
    g0 = modes.sheared_lag(0) + local_compliance;
    engine = std::make_unique<ModalHistoryEngine>(modes, steady.force);
  } else {
    throw InputError("", "[rolling] history",
                     "engine \"" + to_string(settings.history) +
                         "\" is not available for the rolling tyre; allowed: \"auto\", \"modal\", \"direct\"");
  }
  // G0 is slightly non-symmetric: within one step the material moves by a cell. Its symmetric
  // part S is taken at the current step, so each step is an exact symmetric LCP; its skew part
  // K (a fraction of a per cent) acts through the previous step's force. A steady state is
  // unchanged by this (F(n) = F(n−1)), and the added error is first order in Δt, like the step
  // discretisation itself. Both history engines see the same split.
  // A tyre whose own modes carry the tread (the two-layer model) responds within the step, while
  // the material moves a cell: its G0 is skewed by several per cent or more (17 % for the
  // passenger two-layer tyre at 80 km/h), and the skew part taken one step late can then feed a
  // round-off perturbation that grows. When that lag would amplify (lagged_skew_growth) the step
  // is solved with the whole G0 instead, by block principal pivoting for P-matrices
  // (pmatrix_lcp.hpp; G0's symmetric part is positive definite, so G0 is a P-matrix),
  // warm-started from the last step's active set.
  const Eigen::MatrixXd g0_symmetric = 0.5 * (g0 + g0.transpose());
  const Eigen::MatrixXd g0_skew = g0 - g0_symmetric;
  const double skewness = g0_skew.cwiseAbs().maxCoeff() / g0.cwiseAbs().maxCoeff();
  const double lag_growth = skewness > 0.0 ? lagged_skew_growth(g0_symmetric, g0_skew, steady.force) : 0.0;
  // The texture law's step is nonlinear too, but for a tyre whose lag would amplify it takes the
  // whole G0 (BiCGSTAB), as the linear step does.
  const bool whole_g0 = (!nonlinear || texture_law) && lag_growth > whole_contact_matrix_above;
  const std::vector<Eigen::Index> shift_back = shift_along_window(grid);
  // The contact matrix depends on x_p − x_q only (a translation-invariant tyre), so a set shifted
  // along the window keeps its factor, and products with it are convolutions along x; checked,
  // not assumed.
  const bool shift_invariant = matrix_unchanged_by(g0, shift_back);
  // The lagged skew part acts through a convolution too (a dense product would stream G0 once
  // more per step).
  std::unique_ptr<WindowConvolution> skew_product;
  if (shift_invariant && !whole_g0 && skewness > 0.0)
    skew_product = std::make_unique<WindowConvolution>(g0_skew, grid.window, grid.lateral);
  Eigen::VectorXd skew_displacement(points);
  // The per-step solver: for a linear tread the LCP with G0's symmetric part S (the skew part
  // lagged) or, for a strongly skewed G0, with the whole G0, both by block principal pivoting
  // with a factor kept across steps (pmatrix_lcp.hpp; S is positive definite, G0 a P-matrix, so
  // each has one solution). A nonlinear tread's step, the nonlinear complementarity problem with
  // S, by Newton over contact sets with the same FFT products (tread_newton_contact.hpp), warm-started
  // from the steady state's compressions and then from the last step's, moved with the road as
  // the linear tread's active set is; or by the KINSOL reference (nonlinear_tread_contact.hpp).
  std::unique_ptr<PMatrixLcpSolver> lcp;
  std::unique_ptr<TreadNewtonContact> springs;
  std::unique_ptr<NonlinearTreadContact> reference_springs;
  std::optional<ContactWindow> window;
  if (shift_invariant) window = ContactWindow{grid.window, grid.lateral};
  // Texture laws: one per cell the window's points meet over the run, cell m·Ny + j centred at
  // the road position m (x(0) + m·dx/p, as the road ring below) on lateral line j.
  const auto road_positions = static_cast<std::size_t>(grid.window) * static_cast<std::size_t>(substeps);
  std::shared_ptr<const CellContactLaws> laws;
  std::shared_ptr<CellLawSprings> cell_springs;
  TyreContactTrace trace;
  if (texture_law) {
    laws = texture_laws_of_run(grid, substeps, road_positions + samples - 1, road, settings, trace);
    cell_springs = std::make_shared<CellLawSprings>(laws, points);
    springs = std::make_unique<TreadNewtonContact>(whole_g0 ? g0 : g0_symmetric, cell_springs, window,
                                                   /*require_symmetric=*/!whole_g0);
  } else if (nonlinear && nonlinear->solver == NonlinearTreadSolver::kinsol) {
    reference_springs =
        std::make_unique<NonlinearTreadContact>(g0_symmetric, nonlinear->stiffness, nonlinear->exponent);
  } else if (nonlinear) {
    springs = std::make_unique<TreadNewtonContact>(g0_symmetric, nonlinear->stiffness, nonlinear->exponent, window);
    springs->warm_start(steady.force);
  } else {
    lcp = std::make_unique<PMatrixLcpSolver>(whole_g0 ? g0 : g0_symmetric, 128, window);
    std::vector<char> in_contact(static_cast<std::size_t>(points), 0);
    for (Eigen::Index p = 0; p < points; ++p) in_contact[static_cast<std::size_t>(p)] = steady.force(p) > 0.0 ? 1 : 0;
    lcp->warm_start(in_contact);
  }

  trace.engine = engine->name();
  trace.indentation = steady.indentation;
  trace.steady_force = steady.force;
  trace.steady_displacement = steady.displacement;
  trace.steady_rolling_resistance = steady.rolling_resistance;
  const auto rows = static_cast<Eigen::Index>(samples);
  trace.time.resize(rows);
  if (settings.keep_fields) {
    trace.force.resize(rows, points);
    trace.displacement.resize(rows, points);
    trace.road.resize(rows, points);
  }
  trace.total_force.resize(rows);
  trace.contact_area.resize(rows);
  trace.contact_length.resize(rows);
  trace.contact_width.resize(rows);
  trace.input_power.resize(rows);
  trace.lcp_iterations.resize(samples);
  trace.state_changes.assign(samples, 0);
  trace.contact_matrix = measure_contact_matrix(whole_g0 || nonlinear ? g0 : g0_symmetric, grid, steady.force);
  std::vector<char> warm(static_cast<std::size_t>(points), 0);
  trace.contact_matrix_skewness = skewness;
  trace.lagged_skew_growth = lag_growth;
  trace.skew_part_lagged = !whole_g0;

  const Eigen::VectorXd h = grid.undeformed_gap();
  Eigen::VectorXd u0(points), r(points), q(points), position(points), deformation(points);
  Eigen::VectorXd previous_force = steady.force;
  // The work of the forces is taken over one cell of travel, i.e. against the state p steps
  // back (p sub-steps per cell), and spread over those p steps: a ring of the last p states,
  // starting in steady rolling.
  std::vector<Eigen::VectorXd> force_ring(static_cast<std::size_t>(substeps), steady.force);
  std::vector<Eigen::VectorXd> deformation_ring(static_cast<std::size_t>(substeps), steady.deformation);
  const double cell_area = grid.dx() * grid.dy();
  bool edge_warned = false;
  if (sink) sink->start(steady);
  const auto loop_started = std::chrono::steady_clock::now();
  // Column i meets the road at step n at x = x(i) + V·n·Δt = x(0) + (i·p + n)·dx/p: the height
  // that column i + 1 met p steps earlier. The filtered heights are kept by m = i·p + n in a ring
  // of W·p per lateral row, so that a step reads the road once per row instead of once per point
  // (the low-pass filter takes 25 road samples each).
  Eigen::MatrixXd road_ring(static_cast<Eigen::Index>(road_positions), grid.lateral);
  const auto filtered_height = [&](std::size_t m, int j) {
    const double x = grid.x(0) + static_cast<double>(m) * grid.dx() / substeps, y = grid.y(j) - 0.5 * grid.width;
    double sum = 0.0;
    for (std::size_t s = 0; s < road_filter.offsets.size(); ++s)
      sum += road_filter.weights[s] * road.height(x + road_filter.offsets[s], y);
    return sum;
  };
  if (!texture_law)
    for (int j = 0; j < grid.lateral; ++j)
      for (std::size_t m = 0; m + 1 < road_positions; ++m)
        road_ring(static_cast<Eigen::Index>(m), j) = filtered_height(m, j);
  // The tread pattern rides with the material, which passes the window with the road (no slip):
  // column i at step n holds the material point s = x(0) + (i·p + n)·dx/p, the road's position,
  // modulo the circumference 2πR = Nθ·dx, i.e. m = i·p + n modulo Nθ·p. Its heights are taken
  // through the road's own taps along s and averaged over the cell across, once, for all Nθ·p
  // positions of a turn: the loop only reads them (no allocation, one subtraction per point).
  const auto pattern_positions = static_cast<std::size_t>(grid.circumferential) * static_cast<std::size_t>(substeps);
  Eigen::MatrixXd pattern_ring;
  if (settings.pattern) {
    pattern_ring.resize(static_cast<Eigen::Index>(pattern_positions), grid.lateral);
    for (int j = 0; j < grid.lateral; ++j)
      for (std::size_t m = 0; m < pattern_positions; ++m) {
        const double s = grid.x(0) + static_cast<double>(m) * grid.dx() / substeps, y = grid.y(j) - 0.5 * grid.width;
        double sum = 0.0;
        for (std::size_t k = 0; k < road_filter.offsets.size(); ++k)
          sum += road_filter.weights[k] * settings.pattern->lateral_mean(s + road_filter.offsets[k], y, grid.dy());
        pattern_ring(static_cast<Eigen::Index>(m), j) = sum;
      }
  }
  // The air in the patch (air_pumping.hpp): its flows at the steady patch's edges.
  std::optional<AirPumping> air;
  Eigen::VectorXd air_gap;
  if (settings.air_pumping) {
    air.emplace(AirPumpingGeometry{grid.window, grid.lateral, grid.dx(), grid.dy(), substeps, dt});
    air_gap.resize(points);
    AirPumpingTrace& a = trace.air_pumping;
    for (Eigen::VectorXd* v : {&a.front_flow, &a.rear_flow, &a.closed_flow, &a.thin_flow, &a.closed_volume, &a.enclosed_volume})
      v->setZero(rows);
    const ContactExtent steady_extent = contact_extent(grid, steady.force);
    a.front_edge_x = grid.x(steady_extent.i_max) + 0.5 * grid.dx();
    a.rear_edge_x = grid.x(steady_extent.i_min) - 0.5 * grid.dx();
  }
  // Ctrl-C is polled every step, also when no progress is shown (a study's cases).
  const CancellationToken cancel;
  for (std::size_t n = 0; n < samples; ++n) {
    const double t = static_cast<double>(n) * dt;
    const std::size_t newest = road_positions - 1 + n;  // m = (W − 1)·p + n
    if (texture_law) {
      // Each point meets its cell's highest point, through the cell's law.
      for (int j = 0; j < grid.lateral; ++j)
        for (int i = 0; i < grid.window; ++i) {
          const std::size_t m = static_cast<std::size_t>(i) * static_cast<std::size_t>(substeps) + n;
          const std::size_t cell = m * static_cast<std::size_t>(grid.lateral) + static_cast<std::size_t>(j);
          const Eigen::Index p = i + static_cast<Eigen::Index>(grid.window) * j;
          r(p) = laws->top(cell);
          cell_springs->assign(p, cell);
        }
      if (n == 0) springs->warm_start(steady.force);
    } else {
      for (int j = 0; j < grid.lateral; ++j) {
        road_ring(static_cast<Eigen::Index>(newest % road_positions), j) = filtered_height(newest, j);
        for (int i = 0; i < grid.window; ++i) {
          const std::size_t m = static_cast<std::size_t>(i) * static_cast<std::size_t>(substeps) + n;
          r(i + static_cast<Eigen::Index>(grid.window) * j) = road_ring(static_cast<Eigen::Index>(m % road_positions), j);
        }
      }
    }
    auto clock = std::chrono::steady_clock::now();
    engine->history(u0);
    trace.history_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
    if (skew_product) {
      skew_product->apply(previous_force, skew_displacement);
      u0 += skew_displacement;
    } else if (!whole_g0 && skewness > 0.0) {
      u0.noalias() += g0_skew * previous_force;
    }
    q = h - Eigen::VectorXd::Constant(points, steady.indentation) + u0 - r;
    // A groove (pattern height < 0) widens the gap as a road valley does.
    if (settings.pattern)
      for (int j = 0; j < grid.lateral; ++j)
        for (int i = 0; i < grid.window; ++i) {
          const std::size_t m = static_cast<std::size_t>(i) * static_cast<std::size_t>(substeps) + n;
          q(i + static_cast<Eigen::Index>(grid.window) * j) -= pattern_ring(static_cast<Eigen::Index>(m % pattern_positions), j);
        }
    // The road moves one cell towards −x per cell of travel (every p steps), and the contacts
    // on its texture with it; the patch outline stays. Of the last active set, as it is or shifted by one cell, take
    // the one that agrees better with the points that penetrate now (q < 0). The contact
    // matrix depends on x_p − x_q only, so the shifted set keeps its factor.
    if (n > 0 && !reference_springs) {
      const std::vector<char>& last = lcp ? lcp->result().basic : springs->in_contact();
      long stay = 0, shift = 0;
      for (Eigen::Index p = 0; p < points; ++p) {
        const bool penetrates = q(p) < 0.0;
        stay += (last[static_cast<std::size_t>(p)] != 0) != penetrates;
        // Shifted, p is active when the point one cell ahead of it (same row) was.
        const Eigen::Index ahead = p + 1;
        const bool shifted_in = ahead < points && shift_back[static_cast<std::size_t>(ahead)] == p &&
                                last[static_cast<std::size_t>(ahead)] != 0;
        shift += shifted_in != penetrates;
      }
      if (shift < stay) {
        if (lcp) lcp->relabel(shift_back, shift_invariant);
        else springs->relabel(shift_back);
      }
    }
    if (lcp) std::copy(lcp->result().basic.begin(), lcp->result().basic.end(), warm.begin());
    if (springs) std::copy(springs->in_contact().begin(), springs->in_contact().end(), warm.begin());
    clock = std::chrono::steady_clock::now();
    const Eigen::VectorXd& force = lcp ? lcp->solve(q).z : springs ? springs->solve(q) : reference_springs->solve(q);
    trace.lcp_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
    // u = G0·f + u⁰ = w − q + u⁰, with the gaps w = G0·f + q that the LCP solvers keep (zero in
    // contact: the point lies on the road); for a nonlinear tread u = S·F + δ + u⁰ = gap − q + u⁰
    // likewise, with its gap q + S·F + δ.
    if (reference_springs) {
      deformation.noalias() = g0_symmetric * force;
      deformation += u0 + reference_springs->compression();
    } else if (springs) {
      deformation = springs->gap() - q + u0;
    } else {
      deformation = lcp->result().w - q + u0;
    }
    position = h + deformation;
    position.array() -= steady.indentation;

    const auto row = static_cast<Eigen::Index>(n);
    trace.time(row) = t;
    if (settings.keep_fields) {
      trace.force.row(row) = force.transpose();
      trace.displacement.row(row) = position.transpose();
      trace.road.row(row) = r.transpose();
    }
    trace.total_force(row) = force.sum();
    if (texture_law) trace.largest_cell_force = std::max(trace.largest_cell_force, force.maxCoeff());
    const ContactExtent extent = contact_extent(grid, force);
    trace.contact_area(row) = extent.points * cell_area;
    trace.contact_length(row) = extent.length(grid);
    trace.contact_width(row) = extent.width(grid);
    if (!edge_warned && extent.points && (extent.i_min == 0 || extent.i_max == grid.window - 1)) {
      trace.warnings.push_back("the contact reaches the edge of the contact window at t = " + std::to_string(t) +
                               " s: lengthen [rolling] contact_window");
      edge_warned = true;
    }
    if (air) {
      // The gap the contact problem has: w = G0·f + q (zero in contact), i.e. q + u − u⁰.
      clock = std::chrono::steady_clock::now();
      air_gap = q + deformation - u0;
      const AirPumpingStep pumped = air->step(air_gap, force);
      AirPumpingTrace& a = trace.air_pumping;
      a.front_flow(row) = pumped.front_flow;
      a.rear_flow(row) = pumped.rear_flow;
      a.closed_flow(row) = pumped.closed_flow;
      a.thin_flow(row) = pumped.thin_flow;
      a.closed_volume(row) = pumped.closed_volume;
      a.enclosed_volume(row) = pumped.enclosed_volume;
      a.most_closed_regions = std::max(a.most_closed_regions, pumped.closed_regions);
      // The first p steps have no state a cell back: they take the first flows there are, so
      // that the record does not start with a jump.
      if (pumped.ready && n == static_cast<std::size_t>(substeps))
        for (Eigen::Index k = 0; k < row; ++k) {
          a.front_flow(k) = pumped.front_flow;
          a.rear_flow(k) = pumped.rear_flow;
          a.closed_flow(k) = pumped.closed_flow;
          a.thin_flow(k) = pumped.thin_flow;
        }
      a.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
    }
    const auto ring = static_cast<std::size_t>(n % static_cast<std::size_t>(substeps));
    trace.input_power(row) = settings.speed * power_per_metre(grid, force, deformation, force_ring[ring],
                                                              deformation_ring[ring]);
    force_ring[ring] = force;
    deformation_ring[ring] = deformation;
    previous_force = force;
    trace.lcp_iterations[n] = lcp ? lcp->result().iterations : springs ? springs->iterations() : reference_springs->iterations();
    if (lcp || springs) {
      const std::vector<char>& now = lcp ? lcp->result().basic : springs->in_contact();
      for (std::size_t p = 0; p < warm.size(); ++p) trace.state_changes[n] += warm[p] != now[p];
    }
    clock = std::chrono::steady_clock::now();
    engine->advance(force);
    trace.history_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
    if (sink) {
      clock = std::chrono::steady_clock::now();
      sink->take(ContactStep{n, t, force, position, r});
      trace.sink_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
    }
    if (progress)
      progress->update(n);
    else
      cancel.throw_if_cancelled();
  }
  if (texture_law && trace.largest_cell_force > laws->force_cap())
    trace.warnings.push_back("a cell carried " + std::to_string(trace.largest_cell_force) +
                             " N, beyond the contact laws' table (" + std::to_string(laws->force_cap()) +
                             " N, a pressure of E* over the cell), where each law is extrapolated linearly");
  trace.step_loop_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - loop_started).count() - trace.sink_seconds;
  if (lcp) {
    trace.lcp_factorisations = lcp->factorisations();
    trace.lcp_cg_iterations = lcp->cg_iterations();
  }
  if (springs) trace.lcp_cg_iterations = springs->cg_iterations();
  if (progress) progress->finish();
  return trace;
}

}  // namespace rollnoise
