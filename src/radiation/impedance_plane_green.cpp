#include "radiation/impedance_plane_green.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/gauss_kronrod.hpp"

namespace rollnoise {

std::complex<double> impedance_plane_green(double k, double r, double z_receiver, double z_source,
                                           std::complex<double> admittance) {
  using Complex = std::complex<double>;
  const Complex i(0.0, 1.0);
  const double height = z_receiver + z_source;  // Z
  const double r1 = std::hypot(r, z_receiver - z_source);
  const double r2 = std::hypot(r, height);
  const bool infinite = std::isinf(admittance.real()) || std::isinf(admittance.imag());
  if (!(k > 0.0) || !std::isfinite(k) || !(r >= 0.0) || !std::isfinite(r) || !(z_receiver >= 0.0) ||
      !(z_source >= 0.0) || !(height > 0.0) || !std::isfinite(height) || !(r1 > 0.0) ||
      std::isnan(admittance.real()) || std::isnan(admittance.imag()) || (!infinite && admittance.real() < 0.0))
    throw std::invalid_argument(
        "impedance_plane_green: k > 0, r >= 0, heights >= 0 with a positive sum, distinct points and Re β >= 0 needed");
  const double four_pi = 4.0 * std::numbers::pi;
  const Complex direct = std::exp(-i * k * r1) / (four_pi * r1);
  const Complex image = std::exp(-i * k * r2) / (four_pi * r2);
  if (admittance == 0.0) return direct + image;
  if (infinite) return direct - image;
  return direct + image + impedance_plane_correction(k, r, height, admittance);
}

std::complex<double> impedance_plane_correction(double k, double r, double height, std::complex<double> admittance,
                                                double relative_tolerance) {
  using Complex = std::complex<double>;
  const Complex i(0.0, 1.0);
  const double r2 = std::hypot(r, height);
  const bool infinite = std::isinf(admittance.real()) || std::isinf(admittance.imag());
  if (!(k > 0.0) || !std::isfinite(k) || !(r >= 0.0) || !std::isfinite(r) || !(height > 0.0) || !std::isfinite(height) ||
      !(relative_tolerance > 0.0) || std::isnan(admittance.real()) || std::isnan(admittance.imag()) ||
      (!infinite && admittance.real() < 0.0))
    throw std::invalid_argument("impedance_plane_correction: k > 0, r >= 0, Z > 0, a positive tolerance and Re β >= 0 needed");
  if (admittance == 0.0) return 0.0;
  if (infinite) return -2.0 * std::exp(-i * k * r2) / (4.0 * std::numbers::pi * r2);
  // The line integral in t = ks: ∫₀^∞ e^{−βt} e^{−ikR}/(kR) dt.
  const Complex beta = admittance;
  const auto line = [&](double t) {
    const double s = t / k;
    const Complex radius = std::sqrt(Complex(r * r + height * height - s * s, -2.0 * height * s));
    return std::exp(-beta * t - i * k * radius) / (k * radius);
  };
  const double kr2 = k * r2;
  const double kz = k * height;
  const double scale = 1.0 / std::abs(beta);
  std::vector<double> breaks{0.0, kr2, kr2 + 1.0, kr2 + 60.0};
  for (const double b : {scale, 10.0 * scale, 40.0 * scale}) breaks.push_back(b);
  for (const double b : {-10.0 * kz, -kz, kz, 10.0 * kz}) breaks.push_back(kr2 + b);
  breaks.erase(std::remove_if(breaks.begin(), breaks.end(), [&](double b) { return !(b >= 0.0 && b <= kr2 + 60.0); }),
               breaks.end());
  std::sort(breaks.begin(), breaks.end());
  // The correction is −(kβ/2π)·∫: an error ε in ∫ is kβε/(2π) against the image's 1/(4πR₂).
  const double tolerance = relative_tolerance / (kr2 * std::max(1.0, std::abs(beta)));
  const Complex integral = integrate_gauss_kronrod(line, breaks, tolerance);
  return -k * beta / (2.0 * std::numbers::pi) * integral;
}

}  // namespace rollnoise
