#include "contact/point_springs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace rollnoise {

PowerLawSprings::PowerLawSprings(Eigen::VectorXd stiffness, double exponent) : k_(std::move(stiffness)), n_(exponent) {
  if (k_.size() > 0 && !(k_.allFinite() && k_.minCoeff() > 0.0))
    throw std::invalid_argument("TreadNewtonContact: the spring stiffnesses k must be finite and > 0");
  if (!(std::isfinite(n_) && n_ >= 1.0))
    throw std::invalid_argument("TreadNewtonContact: the spring exponent n must be finite and ≥ 1 (got " +
                                std::to_string(n_) + ")");
  power_ = n_ == 1.5 ? Power::one_and_a_half : n_ == 2.5 ? Power::two_and_a_half : n_ == 3.0 ? Power::three : Power::general;
}

double PowerLawSprings::lower_power(double magnitude) const {
  // The Hertzian n = 3/2 and its neighbours by square roots, several times cheaper than
  // std::pow, which each contact point otherwise calls a few times per Newton iteration.
  switch (power_) {
    case Power::one_and_a_half:
      return std::sqrt(magnitude);
    case Power::two_and_a_half:
      return magnitude * std::sqrt(magnitude);
    case Power::three:
      return magnitude * magnitude;
    case Power::general:
      break;
  }
  return std::pow(magnitude, n_ - 1.0);
}

void PowerLawSprings::evaluate(Eigen::Index p, double d, double& force, double& slope) const {
  const double magnitude = std::abs(d);
  if (n_ == 1.0) {
    force = k_(p) * d;
    slope = k_(p);
  } else if (n_ == 2.0) {
    force = k_(p) * magnitude * d;
    slope = 2.0 * k_(p) * magnitude;
  } else {
    const double lower = lower_power(magnitude);  // |δ|^{n−1}
    force = k_(p) * lower * d;
    slope = n_ * k_(p) * lower;
  }
}

double PowerLawSprings::compression_of(Eigen::Index p, double y, double a_pp, double guess) const {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const double t = std::abs(y);
  const double c = a_pp * k_(p);
  double d = t;
  if (t == 0.0) {
    d = 0.0;
  } else if (n_ == 1.0) {
    d = t / (1.0 + c);
  } else if (n_ == 2.0) {
    d = 2.0 * t / (1.0 + std::sqrt(1.0 + 4.0 * c * t));  // the root of cδ² + δ = t, no cancellation
  } else {
    // g(δ) = δ + cδⁿ − t is increasing and convex on δ > 0: Newton from above the root decreases
    // onto it monotonically, and from below its first step lands above it. The last step's
    // compression is close; min(t, (t/c)^{1/n}) bounds the root from above otherwise.
    d = guess != 0.0 ? std::abs(guess) : std::min(t, std::pow(t / c, 1.0 / n_));
    for (int i = 0; i < 100; ++i) {
      const double lower = lower_power(d);
      const double change = (d + c * lower * d - t) / (1.0 + c * n_ * lower);
      d -= change;
      if (std::abs(change) <= 4.0 * eps * d) break;
    }
  }
  return std::copysign(d, y);
}

double PowerLawSprings::compression_at(Eigen::Index p, double force) const {
  return force > 0.0 ? std::pow(force / k_(p), 1.0 / n_) : 0.0;  // δ = (F/k)^{1/n}
}

double PowerLawSprings::stored_energy(Eigen::Index p, double delta) const {
  double force = 0.0, slope = 0.0;
  evaluate(p, std::abs(delta), force, slope);
  return force * std::abs(delta) / (n_ + 1.0);  // ∫ k·δⁿ = k·δ^{n+1}/(n + 1)
}

}  // namespace rollnoise
