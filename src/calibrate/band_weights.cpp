#include "calibrate/band_weights.hpp"

#include <cmath>
#include <map>

namespace rollnoise {

int third_octave_band(double frequency_hz) {
  return static_cast<int>(std::lround(10.0 * std::log10(frequency_hz / 1000.0)));
}

Eigen::VectorXd band_weights(const Eigen::VectorXd& frequency_hz) {
  std::map<int, int> count;
  for (Eigen::Index k = 0; k < frequency_hz.size(); ++k) ++count[third_octave_band(frequency_hz[k])];
  Eigen::VectorXd w(frequency_hz.size());
  for (Eigen::Index k = 0; k < frequency_hz.size(); ++k) w[k] = 1.0 / count[third_octave_band(frequency_hz[k])];
  return w;
}

}  // namespace rollnoise
