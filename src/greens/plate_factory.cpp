#include "greens/plate_factory.hpp"

#include <limits>
#include <stdexcept>

#include "core/config_table.hpp"
#include "core/error.hpp"

namespace rollnoise {

TreadSettings read_tread(const ConfigTable& tyre) {
  const auto table = tyre.subtable("tread");
  if (!table) tyre.fail("tread", "is required: a [tyre.tread] table with type = \"winkler\", \"halfspace\" or \"nonlinear\"");
  const ConfigTable& t = *table;
  TreadSettings tread;
  const std::string type = t.choice("type", {"winkler", "halfspace", "nonlinear"});
  if (type == "winkler") {
    tread.type = TreadSettings::Type::winkler;
    tread.stiffness_per_area = t.positive("stiffness_per_area");
    // The rubber the texture contact law presses onto the road: optional here.
    if (t.contains("youngs_modulus")) tread.youngs_modulus = t.positive("youngs_modulus");
    tread.poisson_ratio = t.between("poisson_ratio", -1.0, 0.5, 0.48);
  } else if (type == "halfspace") {
    tread.type = TreadSettings::Type::halfspace;
    tread.youngs_modulus = t.positive("youngs_modulus");
    tread.poisson_ratio = t.between("poisson_ratio", -1.0, 0.5, 0.48);
  } else {
    tread.type = TreadSettings::Type::nonlinear;
    tread.spring_stiffness = t.positive("spring_stiffness");
    tread.spring_exponent = t.number("spring_exponent", 1.5);
    if (!(tread.spring_exponent >= 1.0)) t.fail("spring_exponent", "must be >= 1");
  }
  t.reject_unknown_keys();
  return tread;
}

PlateTyre read_plate_tyre(const ConfigTable& tyre) {
  tyre.choice("model", {"plate"});
  PlateTyre result;
  PlateParameters& p = result.plate;
  p.radius = tyre.positive("radius");
  p.width = tyre.positive("width");
  p.mass_per_area = tyre.positive("mass_per_area");
  p.tension_x = tyre.non_negative("tension_x");
  p.tension_y = tyre.non_negative("tension_y");
  p.bending_x = tyre.non_negative("bending_x");
  p.bending_y = tyre.non_negative("bending_y");
  p.bending_xy = tyre.non_negative("bending_xy");
  p.foundation_stiffness = tyre.positive("foundation_stiffness");
  p.loss_factor = tyre.non_negative("loss_factor");
  p.circumferential_modes = static_cast<int>(tyre.integer("circumferential_modes", 0, 0, 100000));
  p.lateral_modes = static_cast<int>(tyre.integer("lateral_modes", 0, 1, 10000));
  if (!tyre.contains("circumferential_modes")) tyre.fail("circumferential_modes", "is required (an integer >= 0)");
  if (!tyre.contains("lateral_modes")) tyre.fail("lateral_modes", "is required (an integer >= 1)");
  result.crown_radius = tyre.non_negative("crown_radius", 0.0);
  result.tread_width = tyre.positive("tread_width", p.width);
  if (result.tread_width > p.width) tyre.fail("tread_width", "must not exceed the belt width (" + std::to_string(p.width) + " m)");
  result.tread = read_tread(tyre);
  tyre.contains("pattern");  // [tyre.pattern]: the tread pattern, read for rolling (contact/tread_pattern_reader.hpp)
  tyre.reject_unknown_keys();
  try {
    const KroppPlate check(p);
  } catch (const std::invalid_argument& error) {
    throw InputError(tyre.source_of("model"), "[" + tyre.section() + "]", error.what());
  }
  return result;
}

}  // namespace rollnoise
