#pragma once
// The least-squares line z ≈ mean + slope·(i − centre) through a line's samples over their index
// i, centre = (n − 1)/2: what texture analyses remove before they look at a profile (ISO 13473-1's
// slope suppression, ISO 13473-4's detrending). One place for every analysis that removes it.
#include <cstddef>
#include <span>

namespace rollnoise {

struct LeastSquaresLine {
  double mean = 0.0;
  double slope = 0.0;   // per sample
  double centre = 0.0;  // (n − 1)/2
  // The line's value at sample i.
  double at(std::size_t i) const { return mean + slope * (static_cast<double>(i) - centre); }
};

// The line through `z` (at least one sample; a single sample has slope 0).
inline LeastSquaresLine least_squares_line(std::span<const double> z) {
  LeastSquaresLine line;
  const auto n = static_cast<double>(z.size());
  line.centre = (n - 1.0) / 2.0;
  for (double v : z) line.mean += v;
  line.mean /= n;
  double stt = 0.0, stz = 0.0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    const double t = static_cast<double>(i) - line.centre;
    stt += t * t;
    stz += t * (z[i] - line.mean);
  }
  line.slope = stt > 0.0 ? stz / stt : 0.0;
  return line;
}

}  // namespace rollnoise
