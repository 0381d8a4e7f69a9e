#include "greens/two_layer_factory.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>

#include "core/config_table.hpp"
#include "core/error.hpp"
#include "greens/causal_modulus.hpp"

namespace rollnoise {
namespace {

constexpr std::array<std::string_view, 29> keys = {
    "model", "radius", "width",
    "belt_thickness", "belt_density", "belt_youngs_modulus_x", "belt_youngs_modulus_y", "belt_youngs_modulus_z",
    "belt_shear_modulus_xy", "belt_shear_modulus_xz", "belt_shear_modulus_yz", "belt_poisson_xy",
    "belt_poisson_xz", "belt_poisson_yz", "belt_loss_factor",
    "tread_thickness", "tread_density", "tread_youngs_modulus", "tread_poisson_ratio", "tread_loss_factor",
    "tension_x", "tension_y", "foundation_stiffness", "foundation_loss_factor",
    "circumferential_modes", "lateral_modes", "side_condition", "crown_radius", "tread_width"};

// η ≥ 0 below what the causal modulus can carry; required unless `optional`, then 0 when absent.
double loss_factor(const ConfigTable& tyre, std::string_view key, bool optional = false) {
  const double eta = optional ? tyre.non_negative(key, 0.0) : tyre.non_negative(key);
  if (!(eta < CausalModulus::largest_loss_factor())) {
    tyre.fail(key, "must be < " + std::to_string(CausalModulus::largest_loss_factor()) +
                       " (got " + std::to_string(eta) +
                       "): the causal modulus with nearly constant loss from 10 Hz to 100 kHz cannot carry more");
  }
  return eta;
}

// The first parameter named in a message of the physical checks (they name parameters by their
// key), or `fallback`.
std::string_view named_key(const std::string& message, std::string_view fallback) {
  std::string_view best = fallback;
  std::size_t where = std::string::npos;
  for (const std::string_view key : keys) {
    const std::size_t at = message.find(key);
    // Prefer the earliest mention; among keys at the same place, the longest (belt_poisson_xy
    // over a prefix of it).
    if (at != std::string::npos && (at < where || (at == where && key.size() > best.size()))) {
      where = at;
      best = key;
    }
  }
  return best;
}

}  // namespace

TwoLayerParameters read_two_layer_tyre(const ConfigTable& tyre) {
  // Unknown keys first: a misspelt key is then reported as such, not as a missing one.
  for (const std::string_view key : keys) tyre.contains(key);
  tyre.contains("pattern");  // [tyre.pattern]: the tread pattern, read for rolling (contact/tread_pattern_reader.hpp)
  tyre.reject_unknown_keys();
  tyre.choice("model", {"two_layer"});

  TwoLayerParameters p;
  p.radius = tyre.positive("radius");
  p.width = tyre.positive("width");
  p.belt_thickness = tyre.positive("belt_thickness");
  p.belt_density = tyre.positive("belt_density");
  p.belt.youngs_x = tyre.positive("belt_youngs_modulus_x");
  p.belt.youngs_y = tyre.positive("belt_youngs_modulus_y");
  p.belt.youngs_z = tyre.positive("belt_youngs_modulus_z");
  p.belt.shear_xy = tyre.positive("belt_shear_modulus_xy");
  p.belt.shear_xz = tyre.positive("belt_shear_modulus_xz");
  p.belt.shear_yz = tyre.positive("belt_shear_modulus_yz");
  p.belt.poisson_xy = tyre.number("belt_poisson_xy");
  p.belt.poisson_xz = tyre.number("belt_poisson_xz");
  p.belt.poisson_yz = tyre.number("belt_poisson_yz");
  p.belt_loss_factor = loss_factor(tyre, "belt_loss_factor");
  p.tread_thickness = tyre.positive("tread_thickness");
  p.tread_density = tyre.positive("tread_density");
  p.tread_youngs_modulus = tyre.positive("tread_youngs_modulus");
  // ν = 0.5 (incompressible) has no finite stiffness; rubber is 0.45–0.499.
  p.tread_poisson_ratio = tyre.number("tread_poisson_ratio");
  if (!(p.tread_poisson_ratio > -1.0 && p.tread_poisson_ratio < 0.5)) {
    tyre.fail("tread_poisson_ratio", "must lie strictly between -1 and 0.5 (got " +
                                         std::to_string(p.tread_poisson_ratio) +
                                         "; rubber is 0.45–0.499, and 0.5 has no finite stiffness)");
  }
  p.tread_loss_factor = loss_factor(tyre, "tread_loss_factor");
  p.tension_x = tyre.non_negative("tension_x");
  p.tension_y = tyre.non_negative("tension_y");
  p.foundation_stiffness = tyre.non_negative("foundation_stiffness");
  p.foundation_loss_factor = loss_factor(tyre, "foundation_loss_factor", true);
  if (!tyre.contains("circumferential_modes")) tyre.fail("circumferential_modes", "is required (an integer >= 0)");
  if (!tyre.contains("lateral_modes")) tyre.fail("lateral_modes", "is required (an integer >= 1)");
  p.circumferential_modes = static_cast<int>(tyre.integer("circumferential_modes", 0, 0, 100000));
  p.lateral_modes = static_cast<int>(tyre.integer("lateral_modes", 1, 1, 10000));
  // The contact geometry (as the plate file's keys): the crowned tread across the width and the
  // width that meets the road. They shape the contact grid, not the layers' response.
  p.crown_radius = tyre.non_negative("crown_radius", 0.0);
  p.tread_width = tyre.positive("tread_width", p.width);
  if (p.tread_width > p.width) tyre.fail("tread_width", "must not exceed the width (" + std::to_string(p.width) + " m)");
  p.side_condition = tyre.choice("side_condition", {"simply_supported", "sliding"}, "simply_supported") == "sliding"
                         ? SideCondition::sliding
                         : SideCondition::simply_supported;
  // The physical checks that involve several keys (a positive-definite belt compliance, the
  // sliding edges' need of a foundation) name the key they concern.
  try {
    const TwoLayerTyre check(p);
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    tyre.fail(named_key(message, "model"), message);
  }
  return p;
}

}  // namespace rollnoise
