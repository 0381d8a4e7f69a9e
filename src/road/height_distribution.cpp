#include "road/height_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rollnoise {

HeightMoments height_moments(std::span<const double> z) {
  if (z.size() < 2) throw std::invalid_argument("height_moments: at least 2 values");
  // Two passes: the mean, then the central moments about it (no cancellation).
  double sum = 0.0;
  for (double v : z) {
    if (!std::isfinite(v)) throw std::invalid_argument("height_moments: a value is not finite");
    sum += v;
  }
  const double n = static_cast<double>(z.size());
  HeightMoments m;
  m.mean = sum / n;
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;
  for (double v : z) {
    const double d = v - m.mean;
    const double d2 = d * d;
    m2 += d2;
    m3 += d2 * d;
    m4 += d2 * d2;
  }
  m2 /= n;
  m3 /= n;
  m4 /= n;
  if (!(m2 > 0.0)) throw std::invalid_argument("height_moments: the values have no spread");
  m.sd = std::sqrt(m2);
  m.skewness = m3 / (m2 * m.sd);
  m.kurtosis = m4 / (m2 * m2);
  return m;
}

double standard_normal_cdf(double u) { return 0.5 * std::erfc(-u / std::numbers::sqrt2); }

HeightDistribution::HeightDistribution(std::vector<double> heights) : sorted_(std::move(heights)) {
  moments_ = height_moments(sorted_);  // checks the count and finiteness
  std::sort(sorted_.begin(), sorted_.end());
}

double HeightDistribution::quantile(double p) const {
  const double n = static_cast<double>(sorted_.size());
  const double position = std::clamp(p, 0.0, 1.0) * n - 0.5;  // p_i = (i + 1/2)/N  <=>  i = pN - 1/2
  if (!(position > 0.0)) return sorted_.front();
  if (!(position < n - 1.0)) return sorted_.back();
  const auto i = static_cast<std::size_t>(position);
  const double f = position - static_cast<double>(i);
  return sorted_[i] + f * (sorted_[i + 1] - sorted_[i]);
}

}  // namespace rollnoise
