#pragma once
// The discrete kernel G[k] of a Green's-function model for a time step Δt (MODEL.md §2):
//   step      (default) force constant over the step that ends at sample n:
//             G[0] = C_local + ∫_0^Δt g_s,  G[k] = ∫_{kΔt}^{(k+1)Δt} g_s;  Σ G[k] = C_static.
//   rectangle the paper's eq. 2 as printed: G[0] = C_local, G[k] = g_s(kΔt)·Δt.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

class GreensModel;

enum class Discretisation { step, rectangle };

Discretisation parse_discretisation(const std::string& name);
std::string to_string(Discretisation d);

struct DiscreteKernel {
  double time_step = 0.0;
  Discretisation discretisation = Discretisation::step;
  // G[0], G[1], …, G[length − 1], each point_count × point_count.
  std::vector<Eigen::MatrixXd> lags;
  // Σ_{k=0}^{∞} G[k]: the static compliance this discretisation converges to (exactly
  // C_static for `step`). The pre-history of a constant load uses it, so a run starts in the
  // discrete static equilibrium.
  Eigen::MatrixXd total;

  Eigen::Index point_count() const { return total.rows(); }
  std::size_t length() const { return lags.size(); }
};

// G[0 … length−1]. The kernel is cut where it has decayed below round-off relative to the
// static compliance, if that comes before `length`.
DiscreteKernel make_discrete_kernel(const GreensModel& model, double time_step, std::size_t length,
                                    Discretisation discretisation);

// Number of lags after which g_s has decayed below round-off (relative 1e-17 of its scale).
std::size_t decay_length(const GreensModel& model, double time_step);

}  // namespace rollnoise
