#pragma once
// n points spread evenly over the unit sphere (Fibonacci lattice): equal areas 4π/n. For the
// radiation tests of spheres (a pulsating sphere's exact field and power).
#include <cmath>
#include <numbers>

#include <Eigen/Core>

namespace rollnoise::test {

inline Eigen::Matrix3Xd fibonacci_sphere(int n) {
  Eigen::Matrix3Xd p(3, n);
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / static_cast<double>(n);
    const double r = std::sqrt(1.0 - z * z);
    p.col(i) << r * std::cos(golden * i), r * std::sin(golden * i), z;
  }
  return p;
}

}  // namespace rollnoise::test
