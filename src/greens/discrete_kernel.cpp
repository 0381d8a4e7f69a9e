#include "greens/discrete_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "greens/greens_model.hpp"

namespace rollnoise {

Discretisation parse_discretisation(const std::string& name) {
  if (name == "step") return Discretisation::step;
  if (name == "rectangle") return Discretisation::rectangle;
  throw std::invalid_argument("unknown discretisation \"" + name + "\"");
}

std::string to_string(Discretisation d) { return d == Discretisation::step ? "step" : "rectangle"; }

std::size_t decay_length(const GreensModel& model, double time_step) {
  // e^{−rate·t} < 1e-17 after t = 39.1/rate; the margin covers polynomial factors such as the
  // t·e^{−at} of critical damping.
  const double settle_time = 45.0 / model.slowest_decay_rate();
  const double lags = std::ceil(settle_time / time_step) + 2.0;
  return static_cast<std::size_t>(std::min(lags, 1e9));
}

DiscreteKernel make_discrete_kernel(const GreensModel& model, double time_step, std::size_t length,
                                    Discretisation discretisation) {
  if (!(time_step > 0.0)) throw std::invalid_argument("time step must be > 0");
  DiscreteKernel kernel;
  kernel.time_step = time_step;
  kernel.discretisation = discretisation;
  const std::size_t settled = decay_length(model, time_step);
  const std::size_t n = std::max<std::size_t>(1, std::min(length, settled));
  kernel.lags.reserve(n);
  const double dt = time_step;
  if (discretisation == Discretisation::step) {
    for (std::size_t k = 0; k < n; ++k) {
      const double t0 = static_cast<double>(k) * dt;
      kernel.lags.push_back(model.smooth_integral(t0, t0 + dt));
    }
    kernel.lags[0] += model.local_compliance();
    kernel.total = model.static_compliance();
  } else {
    kernel.lags.push_back(model.local_compliance());
    for (std::size_t k = 1; k < n; ++k) {
      kernel.lags.push_back(model.smooth_response(static_cast<double>(k) * dt) * dt);
    }
    // The infinite sum of the rectangle rule, to where g_s has decayed.
    kernel.total = Eigen::MatrixXd::Zero(model.point_count(), model.point_count());
    for (std::size_t k = 0; k < n; ++k) kernel.total += kernel.lags[k];
    for (std::size_t k = n; k < settled; ++k) {
      kernel.total += model.smooth_response(static_cast<double>(k) * dt) * dt;
    }
  }
  return kernel;
}

}  // namespace rollnoise
