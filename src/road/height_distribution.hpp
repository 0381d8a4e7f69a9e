#pragma once
// The distribution of a road's heights, as measured: the moments a road engineer quotes
// (skewness, kurtosis) and the empirical quantile function through which a Gaussian road is
// given the measured distribution (profile_surface_road.hpp).
#include <span>
#include <vector>

namespace rollnoise {

// Population moments of a height sample: mean, standard deviation, skewness (third central
// moment / sd^3) and kurtosis (fourth / sd^4; 3 for a Gaussian, not the excess).
struct HeightMoments {
  double mean = 0.0;
  double sd = 0.0;
  double skewness = 0.0;
  double kurtosis = 0.0;
};

// At least 2 finite values with a spread (else std::invalid_argument).
HeightMoments height_moments(std::span<const double> z);

// The standard normal distribution function Phi(u) = (1 + erf(u / sqrt 2)) / 2.
double standard_normal_cdf(double u);

// The empirical distribution of a sample, as a quantile function. The sorted values z_(i),
// i = 0 .. N-1, sit at the plotting positions p_i = (i + 1/2) / N (Hazen); Q(p) is linear between
// them and held at z_(0) and z_(N-1) beyond: a translated road never leaves the measured range.
class HeightDistribution {
 public:
  // `heights`: at least 2 values, all finite (std::invalid_argument).
  explicit HeightDistribution(std::vector<double> heights);

  // Q(p) for p in [0, 1] (clamped).
  double quantile(double p) const;
  // Q(Phi(u)): the height with the same probability below it as u has under the standard normal.
  double from_standard_normal(double u) const { return quantile(standard_normal_cdf(u)); }
  const HeightMoments& moments() const noexcept { return moments_; }
  std::size_t size() const noexcept { return sorted_.size(); }

 private:
  std::vector<double> sorted_;
  HeightMoments moments_;
};

}  // namespace rollnoise
