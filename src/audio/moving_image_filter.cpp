#include "audio/moving_image_filter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>

#include "audio/looped_lagrange.hpp"
#include "core/real_fft_batch.hpp"

namespace rollnoise {
namespace {

using Values = std::vector<std::vector<std::complex<double>>>;  // [node][frequency]

// The emitted frequencies at which Q is evaluated: kFactorsPerOctave to the octave from bin 1
// (fs/n) to Nyquist, bin m lying at position log2(m)/step on the grid.
struct FrequencyGrid {
  double lowest = 0.0;
  double step = 1.0;  // octaves between grid points
  int intervals = 1;
  double frequency(int g) const { return lowest * std::exp2(step * g); }
};

FrequencyGrid frequency_grid(int n, double sample_rate) {
  FrequencyGrid grid;
  grid.lowest = sample_rate / n;
  const double octaves = std::log2(std::max(1.0, std::floor(n / 2.0)));
  grid.intervals = std::max(1, static_cast<int>(std::ceil(octaves * MovingImageFilter::kFactorsPerOctave)));
  grid.step = std::max(octaves, 1e-12) / grid.intervals;
  return grid;
}

// Values on the grid, interpolated linearly in log frequency to bins 1 ... n/2 (bin 0: grid[0]).
std::vector<std::complex<double>> to_bins(const std::vector<std::complex<double>>& on_grid, const FrequencyGrid& grid, int n) {
  std::vector<std::complex<double>> out(static_cast<std::size_t>(n / 2 + 1), on_grid.front());
  for (int m = 1; m <= n / 2; ++m) {
    const double position = std::clamp(std::log2(static_cast<double>(m)) / grid.step, 0.0, static_cast<double>(grid.intervals));
    const auto g = static_cast<std::size_t>(std::min(static_cast<int>(position), grid.intervals - 1));
    const double w = position - static_cast<double>(g);
    out[static_cast<std::size_t>(m)] = on_grid[g] + w * (on_grid[g + 1] - on_grid[g]);
  }
  return out;
}

void check_finite(std::complex<double> value, double frequency, const std::string& where) {
  if (!std::isfinite(value.real()) || !std::isfinite(value.imag()))
    throw std::invalid_argument("pass_by: settings.ground_reflection_factor must be finite (at " + std::to_string(frequency) +
                                " Hz" + where + ")");
}

}  // namespace

std::vector<std::complex<double>> response_on_bins(int n, double sample_rate,
                                                   const std::function<std::complex<double>(double)>& response) {
  const FrequencyGrid grid = frequency_grid(n, sample_rate);
  std::vector<std::complex<double>> on_grid(static_cast<std::size_t>(grid.intervals) + 1);
  for (int g = 0; g <= grid.intervals; ++g) {
    on_grid[static_cast<std::size_t>(g)] = response(grid.frequency(g));
    check_finite(on_grid[static_cast<std::size_t>(g)], grid.frequency(g), "");
  }
  return to_bins(on_grid, grid, n);
}

Eigen::VectorXcd looped_spectrum(RealFftBatch& fft, const Eigen::VectorXd& source) {
  const auto n = static_cast<int>(source.size());
  for (int i = 0; i < n; ++i) fft.at(0, i) = source[i];
  fft.forward();
  Eigen::VectorXcd spectrum(fft.bins());
  for (int m = 0; m < fft.bins(); ++m) spectrum[m] = fft.bin(0, m);
  return spectrum;
}

Eigen::VectorXd filtered_loop(RealFftBatch& fft, const Eigen::VectorXcd& spectrum,
                              const std::function<std::complex<double>(int bin)>& gain) {
  const int n = fft.length();
  for (int m = 0; m < fft.bins(); ++m) {
    std::complex<double> g = gain(m);
    if (2 * m == n) g = g.real();
    fft.bin(0, m) = spectrum[m] * g;
  }
  fft.backward();
  Eigen::VectorXd out(n);
  for (int i = 0; i < n; ++i) out[i] = fft.at(0, i) / n;
  return out;
}

MovingImageFilter::MovingImageFilter(const Eigen::VectorXd& source, double sample_rate, const Geometry& geometry,
                                     const Factor& factor)
    : geometry_(geometry),
      eta_first_(std::asinh(geometry.first / geometry.closest)),
      eta_last_(std::max(std::asinh(geometry.last / geometry.closest), eta_first_ + 1e-9)) {
  const auto n = static_cast<int>(source.size());
  const FrequencyGrid grid = frequency_grid(n, sample_rate);
  const auto frequencies = static_cast<std::size_t>(grid.intervals) + 1;

  // Q at node ξ at every grid frequency, the wave's frequency in the air taken along the image
  // path at emission (the Doppler factor of the header).
  const auto evaluate = [&](double node) {
    const double x = position(node);
    const double rho = std::hypot(geometry.closest, x);
    const double doppler = 1.0 / (1.0 - geometry.mach * (-x / std::hypot(rho, geometry.image_height)));
    std::vector<std::complex<double>> q(frequencies);
    for (std::size_t g = 0; g < frequencies; ++g) {
      q[g] = factor(grid.frequency(static_cast<int>(g)) * doppler, rho);
      check_finite(q[g], grid.frequency(static_cast<int>(g)) * doppler, ", " + std::to_string(rho) + " m");
    }
    return q;
  };
  const auto lobatto = [](int j, int degree) { return std::cos(std::numbers::pi * j / degree); };

  // The coefficients a_k (k = 0 ... N, the first and last halved as the series uses them) from
  // the values at the N + 1 Chebyshev–Lobatto nodes cos(πj/N) (a discrete cosine transform).
  const auto coefficients = [&](const Values& values, int degree) {
    Values a(static_cast<std::size_t>(degree) + 1, std::vector<std::complex<double>>(frequencies));
    for (int k = 0; k <= degree; ++k) {
      for (int j = 0; j <= degree; ++j) {
        const double end = (j == 0 || j == degree) ? 0.5 : 1.0;
        const double c = end * std::cos(std::numbers::pi * j * k / degree) * 2.0 / degree;
        for (std::size_t g = 0; g < frequencies; ++g)
          a[static_cast<std::size_t>(k)][g] += c * values[static_cast<std::size_t>(j)][g];
      }
      if (k == 0 || k == degree)
        for (auto& v : a[static_cast<std::size_t>(k)]) v *= 0.5;
    }
    return a;
  };
  const auto series = [](const Values& a, std::size_t g, double xi) {
    std::complex<double> sum = a[0][g];
    double previous = 1.0, current = xi;
    for (std::size_t k = 1; k < a.size(); ++k) {
      sum += a[k][g] * current;
      const double next = 2.0 * xi * current - previous;
      previous = current;
      current = next;
    }
    return sum;
  };

  // Doubling the degree: the nodes of 2N are those of N and the N points between them, at which
  // the degree-N series is checked before they join.
  int degree = 8;
  Values values;
  for (int j = 0; j <= degree; ++j) values.push_back(evaluate(lobatto(j, degree)));
  for (;;) {
    const Values a = coefficients(values, degree);
    Values between;
    double error = 0.0;
    for (int j = 0; j < degree; ++j) {
      const double node = lobatto(2 * j + 1, 2 * degree);
      between.push_back(evaluate(node));
      for (std::size_t g = 0; g < frequencies; ++g) error = std::max(error, std::abs(series(a, g, node) - between.back()[g]));
    }
    Values doubled;
    for (int j = 0; j <= 2 * degree; ++j)
      doubled.push_back(j % 2 == 0 ? values[static_cast<std::size_t>(j / 2)] : between[static_cast<std::size_t>(j / 2)]);
    values = std::move(doubled);
    degree *= 2;
    if (error <= kSeriesTolerance) break;  // and the doubled series, at no further cost, is used
    if (degree + 1 > kMostTerms)
      throw std::invalid_argument("pass_by: the ground reflection factor varies too fast along the pass-by for a "
                                  "series of " + std::to_string(kMostTerms) + " terms (error " + std::to_string(error) + ")");
  }
  const Values coefficient = coefficients(values, degree);

  // Each coefficient, interpolated to the source's bins, filters the looped source; the mean is
  // kept (Q = 1 at zero frequency: the first term alone).
  RealFftBatch fft(n, 1);
  const Eigen::VectorXcd spectrum = looped_spectrum(fft, source);
  for (std::size_t k = 0; k < coefficient.size(); ++k) {
    const std::vector<std::complex<double>> on_bins = to_bins(coefficient[k], grid, n);
    filtered_.push_back(filtered_loop(fft, spectrum, [&](int m) -> std::complex<double> {
      return m == 0 ? (k == 0 ? 1.0 : 0.0) : on_bins[static_cast<std::size_t>(m)];
    }));
  }
}

double MovingImageFilter::position(double node) const {
  return geometry_.closest * std::sinh(eta_first_ + 0.5 * (node + 1.0) * (eta_last_ - eta_first_));
}

double MovingImageFilter::at(double x, double u) const {
  const LoopedLagrangeTaps taps = looped_lagrange_taps(u, filtered_.front().size());
  const double t = std::clamp(2.0 * (std::asinh(x / geometry_.closest) - eta_first_) / (eta_last_ - eta_first_) - 1.0, -1.0, 1.0);
  double sum = read_looped(filtered_[0], taps);
  double previous = 1.0, current = t;
  for (std::size_t k = 1; k < filtered_.size(); ++k) {
    sum += current * read_looped(filtered_[k], taps);
    const double next = 2.0 * t * current - previous;
    previous = current;
    current = next;
  }
  return sum;
}

}  // namespace rollnoise
