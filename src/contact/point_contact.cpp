#include "contact/point_contact.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>

#include "contact/history_engine.hpp"
#include "contact/lcp_solver.hpp"
#include "contact/static_contact.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "greens/discrete_kernel.hpp"
#include "greens/greens_model.hpp"
#include "road/road_profile.hpp"

namespace rollnoise {

std::vector<std::string> check_time_step(const GreensModel& model, double time_step) {
  std::vector<std::string> warnings;
  // Δt·ω ≤ 0.2 keeps about 30 samples per period of the fastest motion; beyond that the
  // first-order discretisation error grows past a few per cent.
  const double rate = model.fastest_rate();
  if (time_step * rate > 0.2) {
    std::ostringstream text;
    text << "[rolling] time_step = " << time_step << " s is coarse for the model's fastest dynamics ("
         << rate << " rad/s, period " << 2.0 * std::numbers::pi / rate << " s); use at most " << 0.2 / rate
         << " s for accurate forces";
    warnings.push_back(text.str());
  }
  return warnings;
}

ContactTrace simulate_point_contact(const GreensModel& model, const RoadProfile& road,
                                    const RollingSettings& settings, ProgressReporter* progress) {
  const Eigen::Index points = model.point_count();
  const std::size_t steps = settings.steps();
  const std::size_t samples = steps + 1;
  const double dt = settings.time_step;

  auto kernel = std::make_shared<const DiscreteKernel>(
      make_discrete_kernel(model, dt, samples, settings.discretisation));
  std::unique_ptr<LcpSolver> lcp;
  try {
    lcp = std::make_unique<LcpSolver>(kernel->lags[0]);
  } catch (const NotPositiveDefiniteError& error) {
    throw InputError("", "[tyre]", std::string(error.what()) +
                                       "; the model's parameters give no unique contact solution");
  }

  // Point models stand at equal height: h = 0. The static contact uses the discretisation's
  // own static compliance, so a flat road keeps exactly the static load.
  const Eigen::VectorXd undeformed = Eigen::VectorXd::Zero(points);
  const StaticContact preload = solve_static_contact(kernel->total, undeformed, settings.static_load);
  auto engine = make_history_engine(settings.history, kernel, samples, preload.force);

  ContactTrace trace;
  trace.time.resize(static_cast<Eigen::Index>(samples));
  trace.road.resize(static_cast<Eigen::Index>(samples), points);
  trace.displacement.resizeLike(trace.road);
  trace.force.resizeLike(trace.road);
  trace.gap.resizeLike(trace.road);
  trace.lcp_iterations.resize(samples);
  trace.indentation = preload.indentation;
  trace.preload_force = preload.force;
  trace.engine = engine->name();
  trace.warnings = check_time_step(model, dt);

  const std::vector<double> offsets = model.contact_point_offsets();
  const Eigen::MatrixXd& g0 = kernel->lags[0];
  Eigen::VectorXd u0(points), r(points), q(points), u(points);
  for (std::size_t n = 0; n < samples; ++n) {
    const double t = static_cast<double>(n) * dt;
    const double x = settings.speed * t;
    for (Eigen::Index i = 0; i < points; ++i) r(i) = road.height(x - offsets[static_cast<std::size_t>(i)]);
    engine->history(u0);
    q = undeformed.array() - preload.indentation + u0.array() - r.array();
    const Eigen::VectorXd& force = lcp->solve(q);
    u.noalias() = g0 * force;
    u += u0;
    const auto row = static_cast<Eigen::Index>(n);
    trace.time(row) = t;
    trace.road.row(row) = r.transpose();
    trace.force.row(row) = force.transpose();
    trace.gap.row(row) = lcp->slack().transpose();
    trace.displacement.row(row) = (undeformed.array() - preload.indentation + u.array()).transpose();
    trace.lcp_iterations[n] = lcp->iterations();
    engine->advance(force);
    if (progress) progress->update(n);
  }
  if (progress) progress->finish();
  return trace;
}

}  // namespace rollnoise
