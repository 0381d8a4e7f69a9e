#include "road/rolled_mastic.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace rollnoise {

double mastic_top(std::uint64_t occupied, double share) {
  std::uint64_t free = ~occupied;
  if (static_cast<double>(std::popcount(free)) < share) return mastic_levels;
  // The k-th free level from the bottom (k = ceil(share), 1-based) is the one the mastic's
  // surface lies in, share − (k − 1) of it filled.
  const double k = std::max(1.0, std::ceil(share));
  for (double i = 1.0; i < k; i += 1.0) free &= free - 1;  // drop the lowest k − 1 free levels
  const int level = std::countr_zero(free);
  return level + (share - (k - 1.0));
}

double mastic_offset(const std::vector<std::uint64_t>& occupied, double share) {
  std::vector<int> free(occupied.size());
  double capacity = 0.0;
  for (std::size_t i = 0; i < occupied.size(); ++i) {
    free[i] = std::popcount(~occupied[i]);
    capacity += free[i];
  }
  const double wanted = share * static_cast<double>(occupied.size());
  if (!(capacity >= wanted)) {
    throw std::invalid_argument("mastic_offset: the pore space of the layer cannot hold the mix's mastic");
  }
  const auto placed = [&](double offset) {
    double sum = 0.0;
    for (int f : free) sum += std::min(share + offset, static_cast<double>(f));
    return sum;
  };
  // placed() is continuous and increasing in the offset up to the largest column's free levels.
  double lo = 0.0, hi = mastic_levels;
  if (placed(lo) >= wanted) return 0.0;
  while (hi - lo > 1e-9) {
    const double mid = 0.5 * (lo + hi);
    (placed(mid) < wanted ? lo : hi) = mid;
  }
  return hi;
}

void smooth_mastic_surface(std::vector<double>& levels, std::size_t nx, std::size_t ny, std::size_t radius) {
  if (radius == 0 || levels.empty()) return;
  // Separable box sums by running sums (the radius is tens of samples), along y within each row,
  // then along x; each window clipped to the grid. In fixed point (2^-32 of a level), so that the
  // sums are exact: a sample's mean does not depend on how far the grid reaches beyond its window
  // (a tile's strip and the whole width give the same bits).
  constexpr double unit = 4294967296.0;  // 2^32
  std::vector<std::int64_t> fixed(levels.size());
  for (std::size_t c = 0; c < levels.size(); ++c) {
    if (!(levels[c] >= 0.0 && levels[c] <= mastic_levels)) {
      throw std::invalid_argument("smooth_mastic_surface: a level outside [0, 64]");
    }
    fixed[c] = std::llround(levels[c] * unit);
  }
  std::vector<std::int64_t> sums(std::max(nx, ny) + 1), counts_y(ny);
  const auto window = [radius](std::size_t m, std::size_t n) {
    return std::pair{m >= radius ? m - radius : 0, std::min(n - 1, m + radius)};
  };
  for (std::size_t i = 0; i < nx; ++i) {
    std::int64_t* row = fixed.data() + i * ny;
    sums[0] = 0;
    for (std::size_t j = 0; j < ny; ++j) sums[j + 1] = sums[j] + row[j];
    for (std::size_t j = 0; j < ny; ++j) {
      const auto [lo, hi] = window(j, ny);
      row[j] = sums[hi + 1] - sums[lo];
    }
  }
  for (std::size_t j = 0; j < ny; ++j) {
    const auto [lo_y, hi_y] = window(j, ny);
    sums[0] = 0;
    for (std::size_t i = 0; i < nx; ++i) sums[i + 1] = sums[i] + fixed[i * ny + j];
    for (std::size_t i = 0; i < nx; ++i) {
      const auto [lo, hi] = window(i, nx);
      const auto count = static_cast<double>((hi - lo + 1) * (hi_y - lo_y + 1));
      levels[i * ny + j] = static_cast<double>(sums[hi + 1] - sums[lo]) / unit / count;
    }
  }
}

}  // namespace rollnoise
