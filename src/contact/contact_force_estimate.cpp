#include "contact/contact_force_estimate.hpp"

#include <complex>
#include <stdexcept>

namespace rollnoise {

double single_point_force_transfer(const KroppPlate& plate, double contact_stiffness, double y0, double omega) {
  if (!(contact_stiffness > 0.0)) throw std::invalid_argument("single_point_force_transfer: k_c must be > 0");
  const std::complex<double> compliance = 1.0 / contact_stiffness + plate.receptance(0.0, y0, y0, omega);
  return 1.0 / std::norm(compliance);
}

}  // namespace rollnoise
