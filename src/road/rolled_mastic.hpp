#pragma once
// The mastic's free surface in a rolled dense mix (aggregate_road.hpp, texture = "rolled"),
// column by column.
//
// The layer of one largest stone's thickness T under the roller's plane is cut into
// `mastic_levels` horizontal levels; a column of the road's grid is described by which levels
// a stone occupies (bit ℓ of a 64-bit word: the level's centre lies inside some stone). The mix
// is uniform at the scale of its mastic, so every column receives the same volume of mastic per
// unit area, V_m·T, and the mastic fills the column's pore space from the bottom of the layer
// up; the column's mastic surface is where that volume is used up. A column whose pore space
// cannot hold it is filled to the plane, and the volume it cannot take goes to the others: one
// offset δ added to every column's share keeps the mastic's total (mastic_offset). Under the
// roller the mastic flows and levels out within the pocket between neighbouring stones, which is
// as wide as the largest of them: the columns' levels are averaged over a square of the largest
// stone's size (smooth_mastic_surface).
//
// This replaces a flat mastic level, the same for every column (a pocket as wide as the road),
// which left 58 % of an AC 8's surface on one floor below sparse stone tops: heights skewed
// positively (+0.7) where measured dense asphalt is skewed negatively (−0.3). With the level set
// by each pocket's own pore space, the mastic reaches the plane where stones crowd the layer and
// stays low only where it holds little stone: broad tops, narrow voids. The averaging width
// decides the skewness (docs/road_aggregate_model.md gives the measured dependence); no measured
// flow length of mastic under a roller could be read, and the largest stone is the scale the
// construction already uses for its layer.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rollnoise {

// Levels over the layer of thickness T (the bits of a column's word).
constexpr int mastic_levels = 64;

// The bits of the levels whose centres z_ℓ = −T + (ℓ + ½)·T/64 lie in [lo, hi] (m, with
// thickness T): the levels one stone occupies in a column. Inline: it runs for every column under
// every stone.
inline std::uint64_t occupied_levels(double lo, double hi, double thickness) {
  const double per_level = mastic_levels / thickness;
  // Levels ℓ with lo ≤ −T + (ℓ + ½)·dz ≤ hi.
  const double first = std::max(std::ceil((lo + thickness) * per_level - 0.5), 0.0);
  const double last = std::min(std::floor((hi + thickness) * per_level - 0.5), static_cast<double>(mastic_levels - 1));
  if (!(first <= last)) return 0;
  const auto from = static_cast<unsigned>(first), to = static_cast<unsigned>(last);
  const std::uint64_t upto = to == 63 ? ~std::uint64_t{0} : (std::uint64_t{1} << (to + 1)) - 1;
  return upto & ~((std::uint64_t{1} << from) - 1);
}

// The mastic's surface in a column, in levels above the layer's bottom (0 … 64; 64 is the
// roller's plane): where `share` levels' worth of mastic (> 0) is used up filling the free
// levels from the bottom up (the partly filled level linearly). 64 when the free levels hold
// less than `share`.
double mastic_top(std::uint64_t occupied, double share);

// The offset δ (levels, ≥ 0) that keeps the mastic's total when the columns that cannot take
// their share are filled to the plane: Σ min(share + δ, free levels of the column) equals
// share × columns (to 1e-9 of a level). Throws std::invalid_argument if the columns' free levels
// together cannot hold share × columns.
double mastic_offset(const std::vector<std::uint64_t>& occupied, double share);

// Averages `levels` (row-major nx × ny, each in [0, 64]) over squares of (2·radius + 1)²
// samples, each square clipped to the grid (the mean of the samples inside it). The sums are
// exact (fixed point, 2^-32 of a level): a sample's mean is the same bits whatever the grid holds
// beyond its square. A level outside [0, 64]: std::invalid_argument.
void smooth_mastic_surface(std::vector<double>& levels, std::size_t nx, std::size_t ny, std::size_t radius);

}  // namespace rollnoise
