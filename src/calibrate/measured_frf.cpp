#include "calibrate/measured_frf.hpp"

#include <cmath>
#include <numbers>

#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {

std::string MeasuredFrf::name() const {
  if (label.empty()) return source;
  std::string text = source;
  text += ", ";
  text += label;
  return text;
}

void fill_mobility(MeasuredFrf& frf, const std::vector<double>& frequency_hz,
                   const std::vector<std::complex<double>>& values,
                   const std::function<std::string(std::size_t)>& where,
                   std::vector<std::string>& notes) {
  const std::string prefix = frf.label.empty() ? std::string() : frf.label + ", ";
  std::vector<double> f;
  std::vector<std::complex<double>> y;
  std::size_t dc_points = 0;
  for (std::size_t k = 0; k < frequency_hz.size(); ++k) {
    const double hz = frequency_hz[k];
    if (!std::isfinite(hz) || !std::isfinite(values[k].real()) || !std::isfinite(values[k].imag()))
      throw InputError(frf.source, prefix + where(k), "must be finite numbers");
    if (hz < 0.0)
      throw InputError(frf.source, prefix + where(k),
                       "frequency " + format_number(hz) + " Hz is negative; frequencies must be >= 0");
    if (k > 0 && !(hz > frequency_hz[k - 1]))
      throw InputError(frf.source, prefix + where(k),
                       "frequency " + format_number(hz) + " Hz does not follow " + format_number(frequency_hz[k - 1]) +
                           " Hz; frequencies must increase strictly");
    if (hz == 0.0) {
      ++dc_points;
      continue;
    }
    if (values[k] == 0.0)
      throw InputError(frf.source, prefix + where(k),
                       "the " + frf_quantity_name(frf.quantity) + " is 0 at " + format_number(hz) +
                           " Hz; the fit compares logarithms and needs a non-zero value (leave the point out)");
    const double omega = 2.0 * std::numbers::pi * hz;
    const std::complex<double> mobility = to_mobility(values[k], frf.quantity, omega);
    if (!std::isfinite(mobility.real()) || !std::isfinite(mobility.imag()) || mobility == 0.0)
      throw InputError(frf.source, prefix + where(k),
                       "the value " + format_number(std::abs(values[k])) + " at " + format_number(hz) +
                           " Hz gives no finite, non-zero mobility");
    f.push_back(hz);
    y.push_back(mobility);
  }
  if (dc_points > 0) notes.push_back(frf.name() + ": the point at 0 Hz is left out (no phase, no mobility at DC)");
  if (f.empty()) throw InputError(frf.source, frf.label, "holds no data above 0 Hz");
  frf.frequency_hz = Eigen::Map<const Eigen::VectorXd>(f.data(), static_cast<Eigen::Index>(f.size()));
  frf.mobility = Eigen::Map<const Eigen::VectorXcd>(y.data(), static_cast<Eigen::Index>(y.size()));
}

}  // namespace rollnoise
