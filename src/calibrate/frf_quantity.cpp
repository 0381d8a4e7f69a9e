#include "calibrate/frf_quantity.hpp"

#include <cassert>

namespace rollnoise {

std::string frf_quantity_name(FrfQuantity quantity) {
  switch (quantity) {
    case FrfQuantity::receptance:
      return "receptance";
    case FrfQuantity::mobility:
      return "mobility";
    case FrfQuantity::accelerance:
      return "accelerance";
  }
  return "mobility";
}

std::optional<FrfQuantity> parse_frf_quantity(std::string_view name) {
  if (name == "receptance") return FrfQuantity::receptance;
  if (name == "mobility") return FrfQuantity::mobility;
  if (name == "accelerance") return FrfQuantity::accelerance;
  return std::nullopt;
}

std::string frf_quantity_choices() { return "receptance, mobility or accelerance"; }

std::complex<double> to_mobility(std::complex<double> value, FrfQuantity quantity, double omega) {
  assert(omega > 0.0);
  const std::complex<double> i_omega(0.0, omega);
  switch (quantity) {
    case FrfQuantity::receptance:
      return i_omega * value;
    case FrfQuantity::mobility:
      return value;
    case FrfQuantity::accelerance:
      return value / i_omega;
  }
  return value;
}

}  // namespace rollnoise
