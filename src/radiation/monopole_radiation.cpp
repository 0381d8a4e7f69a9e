#include "radiation/monopole_radiation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/real_fft_batch.hpp"

namespace rollnoise {

MonopoleGreen rigid_road_green() {
  return [](const Eigen::Vector3d& x, const Eigen::Vector3d& s, double k) { return helmholtz_green(x, s, k, true); };
}

MonopoleSound radiate_monopoles(const MonopoleSources& sources, double sample_rate, const Eigen::Matrix3Xd& receivers,
                                const Eigen::VectorXd& delays_s, double lowest_hz, double highest_hz,
                                const Eigen::VectorXd& frequency_hz, const Medium& medium, const MonopoleGreen& green) {
  const Eigen::Index samples = sources.flows.rows(), count = sources.flows.cols(), receiver_count = receivers.cols();
  if (count != sources.positions.cols() || delays_s.size() != receiver_count || !(sample_rate > 0.0) || !green)
    throw std::invalid_argument("radiate_monopoles: " + std::to_string(count) + " flows for " +
                                std::to_string(sources.positions.cols()) + " sources, " + std::to_string(delays_s.size()) +
                                " delays for " + std::to_string(receiver_count) + " receivers");
  MonopoleSound out;
  out.frequency_hz = frequency_hz;
  out.sound_power_w = Eigen::VectorXd::Zero(frequency_hz.size());
  out.pressure = Eigen::MatrixXd::Zero(samples, receiver_count);
  if (samples < 2 || count == 0) return out;
  // Zero-padded to an even length at least twice the record: the delays left after the
  // receivers' own (a few tens of cm at most) do not wrap round.
  int length = 2;
  while (length < 2 * samples) length *= 2;
  RealFftBatch flow_fft(length, static_cast<int>(count));
  for (Eigen::Index s = 0; s < count; ++s) {
    const double mean = sources.flows.col(s).mean();
    for (int n = 0; n < length; ++n)
      flow_fft.at(static_cast<int>(s), n) = n < samples ? sources.flows(n, s) - mean : 0.0;
  }
  flow_fft.forward();
  RealFftBatch pressure_fft(length, static_cast<int>(std::max<Eigen::Index>(receiver_count, 1)));
  for (int r = 0; r < static_cast<int>(receiver_count); ++r)
    for (int k = 0; k < pressure_fft.bins(); ++k) pressure_fft.bin(r, k) = 0.0;
  const double bin_hz = sample_rate / length;
  const double two_pi = 2.0 * std::numbers::pi;
  const double rho = medium.density;
  // The power's one-sided mean square per bin of the zero-padded record (Parseval over its
  // `samples` values): ⟨q²⟩ = 2|X_k|²/(N·L).
  const double mean_square = 2.0 / (static_cast<double>(samples) * static_cast<double>(length));
  const Eigen::Vector3d touching(1e-7, 0.0, 0.0);  // Im G is smooth at r → 0; G itself is not
  for (int k = 1; k < length / 2; ++k) {
    const double f = k * bin_hz;
    if (f < lowest_hz || f > highest_hz) continue;
    const double omega = two_pi * f, wavenumber = omega / medium.sound_speed;
    // Sample n is the flow over the step before t_n, i.e. at t_n − Δt/2: advanced by Δt/2.
    const std::complex<double> half_step = std::polar(1.0, 0.5 * omega / sample_rate);
    for (Eigen::Index r = 0; r < receiver_count; ++r) {
      std::complex<double> p = 0.0;
      for (Eigen::Index s = 0; s < count; ++s)
        p += flow_fft.bin(static_cast<int>(s), k) * green(receivers.col(r), sources.positions.col(s), wavenumber);
      // p = iωρ·Q·G, in the receiver's retarded time (its delay taken off).
      pressure_fft.bin(static_cast<int>(r), k) =
          std::complex<double>(0.0, omega * rho) * half_step * p * std::polar(1.0, omega * delays_s(r));
    }
    double power = 0.0;
    for (Eigen::Index a = 0; a < count; ++a)
      for (Eigen::Index b = 0; b < count; ++b) {
        const std::complex<double> cross =
            flow_fft.bin(static_cast<int>(a), k) * std::conj(flow_fft.bin(static_cast<int>(b), k));
        const double im = std::imag(green(sources.positions.col(a) + touching, sources.positions.col(b), wavenumber));
        power += cross.real() * -im;
      }
    power *= omega * rho * mean_square;
    out.total_power_w += power;
    if (frequency_hz.size() > 0) {
      const double spacing = frequency_hz.size() > 1 ? frequency_hz(1) - frequency_hz(0) : 1.0;
      const auto nearest = static_cast<Eigen::Index>(std::lround((f - frequency_hz(0)) / spacing));
      out.sound_power_w(std::clamp<Eigen::Index>(nearest, 0, frequency_hz.size() - 1)) += power;
    }
  }
  if (receiver_count == 0) return out;
  pressure_fft.backward();
  for (Eigen::Index r = 0; r < receiver_count; ++r)
    for (Eigen::Index n = 0; n < samples; ++n)
      out.pressure(n, r) = pressure_fft.at(static_cast<int>(r), static_cast<int>(n)) / length;
  return out;
}

}  // namespace rollnoise
