#include "radiation/radiation_efficiency.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rollnoise {

double radiation_efficiency(double power_w, double density, double sound_speed, double area,
                            double mean_square_velocity) {
  if (!(power_w >= 0.0) || !(density > 0.0) || !(sound_speed > 0.0) || !(area > 0.0) || !(mean_square_velocity > 0.0))
    throw std::invalid_argument("radiation_efficiency: needs W >= 0 and positive ρ, c, S, <v²>");
  return power_w / (density * sound_speed * area * mean_square_velocity);
}

double baffled_piston_radiation_efficiency(double ka) {
  if (!(ka > 0.0)) throw std::invalid_argument("baffled_piston_radiation_efficiency: ka must be > 0");
  if (ka < 1e-3) return 0.5 * ka * ka;  // 1 − J1(2ka)/ka = (ka)²/2 − (ka)⁴/6 + …
  return 1.0 - std::cyl_bessel_j(1.0, 2.0 * ka) / ka;
}

double pulsating_cylinder_radiation_efficiency(double ka) {
  if (!(ka > 0.0)) throw std::invalid_argument("pulsating_cylinder_radiation_efficiency: ka must be > 0");
  const double j1 = std::cyl_bessel_j(1.0, ka);
  const double y1 = std::cyl_neumann(1.0, ka);
  return 2.0 / (std::numbers::pi * ka * (j1 * j1 + y1 * y1));
}

}  // namespace rollnoise
