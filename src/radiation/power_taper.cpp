#include "radiation/power_taper.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rollnoise {

Eigen::VectorXd power_taper(Eigen::Index samples, Eigen::Index ramp) {
  if (samples < 1 || ramp < 0) throw std::invalid_argument("power taper: needs samples >= 1 and ramp >= 0");
  const Eigen::Index length = std::min(ramp, samples / 2);
  Eigen::VectorXd w(samples);
  for (Eigen::Index n = 0; n < samples; ++n) {
    const Eigen::Index from_edge = std::min(n, samples - 1 - n);
    // The ramp's samples sit at half-sample offsets from the edge, so both ends are the same.
    w(n) = from_edge < length
               ? 0.5 * (1.0 - std::cos(std::numbers::pi * (static_cast<double>(from_edge) + 0.5) / static_cast<double>(length)))
               : 1.0;
  }
  return w;
}

}  // namespace rollnoise
