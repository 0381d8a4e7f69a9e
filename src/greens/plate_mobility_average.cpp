#include "greens/plate_mobility_average.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <vector>

namespace rollnoise {
namespace {

// H_mn(ω) for m = 0 … M of one lateral order n.
std::vector<std::complex<double>> modal_responses(const KroppPlate& plate, int n, double omega) {
  const int M = plate.parameters().circumferential_modes;
  const double eta = plate.parameters().loss_factor;
  std::vector<std::complex<double>> h(static_cast<std::size_t>(M) + 1);
  for (int m = 0; m <= M; ++m) {
    const double w = plate.natural_frequency(m, n);
    h[static_cast<std::size_t>(m)] = 1.0 / std::complex<double>(w * w - omega * omega, omega * eta * w);
  }
  return h;
}

}  // namespace

double belt_mean_square_mobility(const KroppPlate& plate, double y0, double omega) {
  const PlateParameters& p = plate.parameters();
  if (!(y0 >= 0.0 && y0 <= p.width)) throw std::invalid_argument("belt_mean_square_mobility: y0 outside the belt");
  double sum = 0.0;
  for (int n = 1; n <= p.lateral_modes; ++n) {
    const double s = std::sin(plate.wavenumber_y(n) * y0);
    const std::vector<std::complex<double>> h = modal_responses(plate, n, omega);
    double orders = std::norm(h[0]);
    for (std::size_t m = 1; m < h.size(); ++m) orders += 2.0 * std::norm(h[m]);  // ±m
    sum += s * s * orders;
  }
  return 0.5 * omega * omega * sum / (plate.modal_mass() * plate.modal_mass());
}

NearMeanSquareMobility::NearMeanSquareMobility(const KroppPlate& plate, double y0, double half_length, double step)
    : plate_(plate), y0_(y0) {
  const PlateParameters& p = plate.parameters();
  if (!(y0 >= 0.0 && y0 <= p.width)) throw std::invalid_argument("near_mean_square_mobility: y0 outside the belt");
  if (!(half_length > 0.0 && half_length <= 0.5 * plate.circumference() * (1 + 1e-12)))
    throw std::invalid_argument("near_mean_square_mobility: half_length must be in (0, L/2]");
  if (!(step > 0.0)) throw std::invalid_argument("near_mean_square_mobility: step must be > 0");
  points_ = std::max(1, static_cast<int>(std::ceil(2.0 * half_length / step)));
  const double h = 2.0 * half_length / points_;
  const int M = p.circumferential_modes;
  // 2·cos(k_m x_i), m = 1 … M, for every midpoint x_i: the same for every n and ω. Stored by m,
  // the points of one m side by side, so that operator() sums all the points at once.
  cosines_.resize(static_cast<std::size_t>(M) * static_cast<std::size_t>(points_));
  for (int m = 1; m <= M; ++m)
    for (int i = 0; i < points_; ++i)
      cosines_[static_cast<std::size_t>(m - 1) * static_cast<std::size_t>(points_) + static_cast<std::size_t>(i)] =
          2.0 * std::cos(plate.wavenumber_x(m) * (-half_length + (i + 0.5) * h));
}

double NearMeanSquareMobility::operator()(double omega) const {
  const PlateParameters& p = plate_.parameters();
  const auto points = static_cast<std::size_t>(points_);
  std::vector<double> sum_re(points), sum_im(points);
  double* re = sum_re.data();
  double* im = sum_im.data();
  double sum = 0.0;
  for (int n = 1; n <= p.lateral_modes; ++n) {
    const double s = std::sin(plate_.wavenumber_y(n) * y0_);
    if (s == 0.0) continue;
    const std::vector<std::complex<double>> hm = modal_responses(plate_, n, omega);
    // a_i = H_0 + Σ_m 2cos(k_m x_i)·H_m (H is even in m: e^{ikx} + e^{−ikx} = 2 cos(kx)), each
    // point's sum in the order of m as one complex sum would take it (the same numbers bit for
    // bit), the points side by side (independent sums the compiler vectorises, issue 12).
    std::fill(re, re + points, hm[0].real());
    std::fill(im, im + points, hm[0].imag());
    for (std::size_t m = 1; m < hm.size(); ++m) {
      const double* c = cosines_.data() + (m - 1) * points;
      const double hr = hm[m].real(), hi = hm[m].imag();
      for (std::size_t i = 0; i < points; ++i) {
        re[i] += c[i] * hr;
        im[i] += c[i] * hi;
      }
    }
    double mean = 0.0;
    for (std::size_t i = 0; i < points; ++i) mean += std::norm(std::complex<double>(re[i], im[i]));
    sum += s * s * mean / points_;
  }
  return 0.5 * omega * omega * sum / (plate_.modal_mass() * plate_.modal_mass());
}

double near_mean_square_mobility(const KroppPlate& plate, double y0, double omega, double half_length, double step) {
  return NearMeanSquareMobility(plate, y0, half_length, step)(omega);
}

std::complex<double> patch_receptance(const KroppPlate& plate, double length, double width, double omega) {
  const PlateParameters& p = plate.parameters();
  if (!(length > 0.0 && length <= plate.circumference())) throw std::invalid_argument("patch_receptance: bad length");
  if (!(width > 0.0 && width <= p.width)) throw std::invalid_argument("patch_receptance: width must be in (0, b]");
  std::complex<double> sum = 0.0;
  for (int n = 1; n <= p.lateral_modes; ++n) {
    const double k = plate.wavenumber_y(n);
    const double across = (std::cos(0.5 * k * (p.width - width)) - std::cos(0.5 * k * (p.width + width))) / (k * width);
    if (across == 0.0) continue;
    const std::vector<std::complex<double>> h = modal_responses(plate, n, omega);
    for (std::size_t m = 0; m < h.size(); ++m) {
      const double a = 0.5 * plate.wavenumber_x(static_cast<int>(m)) * length;
      const double along = m == 0 ? 1.0 : std::sin(a) / a;
      sum += (m == 0 ? 1.0 : 2.0) * along * along * across * across * h[m];  // ±m
    }
  }
  return sum / plate.modal_mass();
}

}  // namespace rollnoise
