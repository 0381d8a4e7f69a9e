#pragma once
// A second mean profile depth, independent of src/road/mean_profile_depth.cpp, for the tests of
// the profile readers (test_laser_profile.cpp, test_line_laser_csv.cpp).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace rollnoise::test {

// --- A second MPD, written from ISO 13473-1:2019's text with plain loops -------------------
// Positions x_i = i·dx. (1) 0.5 mm samples: the mean of the samples in each whole 0.5 mm bin.
// (2) Low pass: the analog 2nd-order Butterworth H(s) = wc²/(s² + √2 wc s + wc²) at the
// 2.4 mm corner, bilinear transform s = (2/T)(1 - 1/z)/(1 + 1/z) with wc pre-warped to
// (2/T) tan(πT/λc), in direct form I, run forward then backward over the profile extended
// by 200 copies of its end values (not the library's odd reflection and steady start).
// (3) 100 mm segments of 200 samples; (4) least-squares line in x (metres) subtracted;
// (5) MSD = (peak of first 100 + peak of last 100)/2 - mean; (6) MPD = mean MSD.
inline double second_mpd(const std::vector<double>& z, double dx) {
  const double bin = 0.5e-3;
  const auto bins = static_cast<std::size_t>(std::floor(static_cast<double>(z.size()) * dx / bin + 1e-9));
  std::vector<double> sum(bins, 0.0), count(bins, 0.0);
  for (std::size_t i = 0; i < z.size(); ++i) {
    const auto k = static_cast<std::size_t>(std::floor(static_cast<double>(i) * dx / bin + 1e-9));
    if (k < bins) {
      sum[k] += z[i];
      count[k] += 1;
    }
  }
  std::vector<double> r(bins);
  for (std::size_t k = 0; k < bins; ++k) r[k] = sum[k] / count[k];

  const double T = bin;
  const double wc = 2 / T * std::tan(std::numbers::pi * T / 2.4e-3);
  const double c = 2 / T;  // s = c (z - 1)/(z + 1)
  // H = wc² (z + 1)² / (c²(z - 1)² + √2 wc c (z - 1)(z + 1) + wc² (z + 1)²), in powers of 1/z:
  const double a0 = c * c + std::sqrt(2.0) * wc * c + wc * wc;
  const double a1 = (-2 * c * c + 2 * wc * wc) / a0;
  const double a2 = (c * c - std::sqrt(2.0) * wc * c + wc * wc) / a0;
  const double b0 = wc * wc / a0, b1 = 2 * wc * wc / a0, b2 = wc * wc / a0;
  const std::size_t pad = 200;
  std::vector<double> x(pad, r.front());
  x.insert(x.end(), r.begin(), r.end());
  x.insert(x.end(), pad, r.back());
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<double> y(x.size());
    double x1 = x[0], x2 = x[0], y1 = x[0], y2 = x[0];
    for (std::size_t i = 0; i < x.size(); ++i) {
      y[i] = b0 * x[i] + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
      x2 = x1;
      x1 = x[i];
      y2 = y1;
      y1 = y[i];
    }
    std::reverse(y.begin(), y.end());
    x = y;
  }
  std::vector<double> f(x.begin() + pad, x.end() - pad);

  const std::size_t segments = f.size() / 200;
  double msd_sum = 0;
  for (std::size_t s = 0; s < segments; ++s) {
    double xm = 0, zm = 0;
    for (std::size_t i = 0; i < 200; ++i) {
      xm += static_cast<double>(i) * bin / 200;
      zm += f[200 * s + i] / 200;
    }
    double sxx = 0, sxz = 0;
    for (std::size_t i = 0; i < 200; ++i) {
      const double xi = static_cast<double>(i) * bin;
      sxx += (xi - xm) * (xi - xm);
      sxz += (xi - xm) * (f[200 * s + i] - zm);
    }
    const double b = sxz / sxx;
    double peak1 = -1e9, peak2 = -1e9, mean = 0;
    for (std::size_t i = 0; i < 200; ++i) {
      const double h = f[200 * s + i] - (zm + b * (static_cast<double>(i) * bin - xm));
      if (i < 100) peak1 = std::max(peak1, h);
      else peak2 = std::max(peak2, h);
      mean += h / 200;
    }
    msd_sum += (peak1 + peak2) / 2 - mean;
  }
  return msd_sum / static_cast<double>(segments);
}

}  // namespace rollnoise::test
