#include "greens/model_factory.hpp"

#include <cmath>

#include "core/config_table.hpp"
#include "core/error.hpp"
#include "greens/sdof_model.hpp"
#include "greens/two_layer_factory.hpp"

namespace rollnoise {
namespace {

SdofParameters read_sdof_parameters(const ConfigTable& tyre) {
  SdofParameters p{};
  p.mass = tyre.positive("mass");
  // An undamped system never reaches the static equilibrium a run starts from.
  p.damping = tyre.positive("damping");
  p.stiffness = tyre.positive("stiffness");
  p.contact_stiffness = tyre.positive("contact_stiffness");
  return p;
}

}  // namespace

std::unique_ptr<GreensModel> make_greens_model(const ConfigTable& tyre) {
  const std::string model = tyre.choice("model", {"sdof", "coupled_sdof"});
  std::unique_ptr<GreensModel> result;
  if (model == "sdof") {
    result = std::make_unique<SdofModel>(read_sdof_parameters(tyre));
  } else {
    const SdofParameters p = read_sdof_parameters(tyre);
    // G[0] = M/s with M = [[1, c], [c, 1]] is positive definite only for |c| < 1.
    const double coupling = tyre.between("coupling", -1.0, 1.0, 0.0);
    const double spacing = tyre.non_negative("spacing");
    result = std::make_unique<SdofModel>(p, coupling, spacing);
  }
  tyre.reject_unknown_keys();
  // Values that are each positive can still combine beyond double range (mass = 1e-300).
  const double fastest = result->fastest_rate();
  const double slowest = result->slowest_decay_rate();
  if (!std::isfinite(fastest) || !(slowest > 0.0) || !result->static_compliance().allFinite()) {
    throw InputError(tyre.source_of("mass"), "[tyre] mass, damping, stiffness, contact_stiffness",
                     "together give rates or compliances outside the range of doubles; use physical values");
  }
  return result;
}

std::unique_ptr<SurfaceReceptanceModel> make_surface_receptance_model(const ConfigTable& tyre) {
  tyre.choice("model", {"two_layer"});
  return std::make_unique<TwoLayerTyre>(read_two_layer_tyre(tyre));
}

}  // namespace rollnoise
