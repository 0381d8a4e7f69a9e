#include "road/texture_waves.hpp"

#include <algorithm>
#include <array>
#include <utility>
#include <cmath>
#include <memory>
#include <new>
#include <numbers>
#include <random>
#include <stdexcept>

#include <fftw3.h>

#include "core/csv.hpp"
#include "core/fftw_plan.hpp"
#include "road/portable_normal.hpp"
#include "road/spectral_synthesis.hpp"

namespace rollnoise {
namespace {

struct FftwFree {
  void operator()(void* p) const noexcept { fftw_free(p); }
};

// Waves drawn together: their lateral wavenumbers take the quantiles (i + v_i)/block of their
// conditional densities, i a random permutation of 0 .. block - 1 and v_i uniform (stratified,
// "Latin hypercube" sampling): neighbouring waves, whose densities differ little, cover them
// evenly, so that a line across the road gets its band levels from many waves rather than from a
// few that happened to fall there.
constexpr std::size_t block = 16;
// Bisection steps within a cell: the cell's width / 2^40, far below any wavenumber that matters.
constexpr int bisection_steps = 40;

}  // namespace

TextureWaveSurface::TextureWaveSurface(const TextureBandPsd& psd, double spacing, std::size_t samples,
                                       std::uint64_t seed, double lead_in, std::function<double(double)> marginal)
    : spacing_(spacing), samples_(samples), lead_in_(lead_in), marginal_(std::move(marginal)) {
  if (!(spacing > 0.0) || samples < 2) throw std::invalid_argument("TextureWaveSurface: spacing > 0 and samples >= 2");
  const double period = spacing * static_cast<double>(samples);
  const double dn = 1.0 / period;
  const double n_max = psd.highest_wavenumber();
  coefficient_.assign(samples / 2 + 1, {0.0, 0.0});
  lateral_.assign(samples / 2 + 1, 0.0);
  std::mt19937_64 engine(seed);
  std::array<std::size_t, block> stratum{};
  std::vector<double> bound;       // cell bounds in k: 0 and sqrt(e^2 - n^2) for each edge e > n
  std::vector<double> edge_value;  // the line integral of S from 0 to each bound
  std::vector<double> weight;      // each cell's integral, clipped at 0
  for (std::size_t m = 1; 2 * m < samples; ++m) {
    const double n = static_cast<double>(m) * dn;
    if (n >= n_max) break;  // no texture at this or any higher wavenumber
    // The integral of S along k >= 0 at this n, in cells between the k where the line crosses a
    // band edge (q = e): within a cell no term of S starts or ends, so S keeps its sign there
    // for a realisable target and clipping a cell at 0 clips exactly where S < 0.
    const double total = psd.isotropic_line_cells(n, bound, edge_value, weight);
    const std::size_t cells = bound.size() - 1;
    if ((m - 1) % block == 0) {  // a new block: a random permutation of the strata (Fisher-Yates)
      for (std::size_t i = 0; i < block; ++i) stratum[i] = i;
      for (std::size_t i = block - 1; i > 0; --i) std::swap(stratum[i], stratum[engine() % (i + 1)]);
    }
    const auto [cos_phi, sin_phi] = portable::random_phasor(engine);
    const double u =
        (static_cast<double>(stratum[(m - 1) % block]) + portable::uniform_closed_open(engine)) / static_cast<double>(block);
    const bool negative = (engine() >> 63) != 0;
    if (!(total > 0.0)) continue;
    // |C_m|^2 = dn · (the density integrated over all k, both signs): G(n)/(2P) where realisable.
    const double modulus = std::sqrt(dn * 2.0 * total);
    coefficient_[m] = {modulus * cos_phi, modulus * sin_phi};
    // The cell that holds the fraction u of the clipped integral, then k within it.
    double target = u * total;
    std::size_t c = 0;
    while (c + 1 < cells && (weight[c] == 0.0 || target >= weight[c])) {
      target -= weight[c];
      ++c;
    }
    double lo = bound[c];
    double hi = bound[c + 1];
    const double scale = weight[c] > 0.0 ? (edge_value[c + 1] - edge_value[c]) / weight[c] : 1.0;
    const double goal = edge_value[c] + std::min(target, weight[c]) * scale;
    for (int step = 0; step < bisection_steps; ++step) {
      const double mid = 0.5 * (lo + hi);
      (psd.isotropic_line_cumulative(n, mid) < goal ? lo : hi) = mid;
    }
    const double k = 0.5 * (lo + hi);
    lateral_[m] = negative ? -k : k;
  }
  double square = 0.0;
  for (const auto& c : coefficient_) square += std::norm(c);
  rms_ = std::sqrt(2.0 * square);
  if (marginal_ && !(rms_ > 0.0)) throw std::invalid_argument("TextureWaveSurface: a marginal needs waves");
}

const std::vector<double>& TextureWaveSurface::line(long j) const {
  if (const auto found = lines_.find(j); found != lines_.end()) return found->second;
  const std::size_t n = samples_;
  std::unique_ptr<fftw_complex[], FftwFree> spectrum(fftw_alloc_complex(n / 2 + 1));
  std::unique_ptr<double[], FftwFree> grid(fftw_alloc_real(n));
  if (!spectrum || !grid) throw std::bad_alloc();
  const FftwPlan plan([&] { return fftw_plan_dft_c2r_1d(static_cast<int>(n), spectrum.get(), grid.get(), FFTW_ESTIMATE); });
  // Each wave at this line: its coefficient turned by the lateral phase 2 pi k_m y.
  const double y = spacing_ * static_cast<double>(j);
  for (std::size_t m = 0; m <= n / 2; ++m) {
    const std::complex<double> z =
        coefficient_[m] * std::polar(1.0, 2.0 * std::numbers::pi * std::remainder(lateral_[m] * y, 1.0));
    spectrum[m][0] = z.real();
    spectrum[m][1] = z.imag();
  }
  plan.execute();
  std::vector<double> values(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    const double g = grid[i % n];
    values[i] = (marginal_ ? marginal_(g / rms_) : g) * lead_in_window(spacing_ * static_cast<double>(i), lead_in_);
  }
  // Hold at most max_synthesis_points samples of lines: drop the oldest first.
  while (!order_.empty() && (lines_.size() + 1) * (n + 1) > max_synthesis_points) {
    lines_.erase(order_.front());
    order_.pop_front();
  }
  order_.push_back(j);
  return lines_.emplace(j, std::move(values)).first->second;
}

double TextureWaveSurface::sample(std::size_t i, long j) const {
  if (i > samples_) {
    throw std::logic_error("TextureWaveSurface: sample " + std::to_string(i) + " is beyond the road's " +
                           std::to_string(samples_) + " samples");
  }
  const std::lock_guard lock(mutex_);
  return line(j)[i];
}

double TextureWaveSurface::height(double x, double y) const {
  if (x < 0.0) return 0.0;  // the flat lead-in (road_profile.hpp)
  const double u = x / spacing_;
  const double v = y / spacing_;
  const double end = static_cast<double>(samples_);
  if (!(u <= end * (1.0 + 1e-12)) || !std::isfinite(v) || !(std::abs(v) < 1e15)) {
    throw std::logic_error("TextureWaveSurface: (" + format_number(x) + ", " + format_number(y) +
                           ") m is outside the road (x up to " + format_number(end * spacing_) + " m)");
  }
  const auto i = std::min(static_cast<std::size_t>(std::floor(u)), samples_ - 1);
  const double fx = std::clamp(u - static_cast<double>(i), 0.0, 1.0);
  const auto j = static_cast<long>(std::floor(v));
  const double fy = v - static_cast<double>(j);
  const std::lock_guard lock(mutex_);
  const std::vector<double>& a = line(j);
  const double za = (1.0 - fx) * a[i] + fx * a[i + 1];
  if (fy == 0.0) return za;
  const std::vector<double>& b = line(j + 1);  // `a` may have been dropped: read it first
  return (1.0 - fy) * za + fy * ((1.0 - fx) * b[i] + fx * b[i + 1]);
}

}  // namespace rollnoise
