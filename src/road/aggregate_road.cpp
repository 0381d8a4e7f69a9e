#include "road/aggregate_road.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <future>
#include <limits>
#include <mutex>
#include <numbers>
#include <optional>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/cancellation.hpp"
#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "road/portable_normal.hpp"
#include "road/rolled_mastic.hpp"
#include "road/spectral_synthesis.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rollnoise {
namespace {

[[noreturn]] void throw_bad(const char* key, const std::string& problem) {
  throw InputError("", key, problem);  // the factory names the file and the section
}

void require_in(const char* key, double value, double lo, bool lo_open, double hi, bool hi_open,
                const std::string& range) {
  const bool ok = std::isfinite(value) && (lo_open ? value > lo : value >= lo) && (hi_open ? value < hi : value <= hi);
  if (!ok) throw_bad(key, "must be in " + range + " (got " + format_number(value) + ")");
}

// How far the "negative" texture's stones would reach above the top plane, as a fraction of c.
constexpr double negative_cut_fraction = 0.3;
// Most stones a road may hold (bounds the time and memory of the placement).
constexpr double max_stones = 1 << 25;

// texture = "rolled": the stone sizes of the grading between dmin and dmax, as intervals of
// sieve sizes whose mass is spread evenly in log size, and the mix's volume fractions.
struct RolledMix {
  struct Interval {
    double lo = 0.0, hi = 0.0;  // m
    double mass_per_log = 0.0;  // mass fraction per unit ln d
    double number = 0.0;        // relative number of stones, ∝ mass_per_log·(lo^-3 − hi^-3)/3
  };
  std::vector<Interval> intervals;
  std::vector<double> cumulative;     // the intervals' cumulative number fractions, ending in 1
  double stones = 0.0;                // V_c, the coarse aggregate's volume fraction
  double mastic = 0.0;                // V_m, binder and fine aggregate
  double depth = 0.0;                 // stones are centred in [−depth, 0] (m)
  double thickness = 0.0;             // T, the layer the mastic fills (m)
  double share = 0.0;                 // each column's mastic, levels of T/64, with the offset δ
  std::size_t smoothing = 0;          // the mastic surface's averaging radius, samples
};

struct Checked {
  double dmax = 0.0, dmin = 0.0, spacing = 0.0, lead_in = 0.0;
  // The flat level between the stones (m), the binder's; for texture = "rolled" the lowest the
  // mastic's surface can lie, below which no stone is seen.
  double base = 0.0;
  RolledMix mix;  // texture = "rolled" only
};

// Densities of the mix's components (kg/m³): typical values for crushed rock and for bitumen.
constexpr double aggregate_density = 2650.0;
constexpr double binder_density = 1030.0;
// The rolled mix's mastic share is found on a reference patch of this many largest stones square
// (at least 0.1 m), from this seed, the same for every road of the mix (rolled_mastic_share).
constexpr double reference_patch_stones = 10.0;
constexpr std::uint64_t reference_patch_seed = 0x524f4c4c4544;  // "ROLLED"

// The mass fraction passing d (0 … 1), linear in ln d between the sieves.
double passing_at(const AggregateRoadSpec& spec, double d) {
  const std::vector<double>& s = spec.sieves;
  const std::vector<double>& p = spec.passing;
  if (d <= s.front()) return p.front() / 100.0;
  for (std::size_t i = 1; i < s.size(); ++i) {
    if (d <= s[i]) {
      const double t = std::log(d / s[i - 1]) / std::log(s[i] / s[i - 1]);
      return (p[i - 1] + t * (p[i] - p[i - 1])) / 100.0;
    }
  }
  return 1.0;
}

// Checks the mix design of texture = "rolled" and fills k.dmax, k.dmin and k.mix (but the
// mastic's share, which needs the shape and the spacing: rolled_mastic_share).
void check_mix(const AggregateRoadSpec& spec, Checked& k) {
  const std::vector<double>& s = spec.sieves;
  const std::vector<double>& p = spec.passing;
  if (s.size() < 2) throw_bad("sieves", "must list at least two sieve sizes (m), increasing, such as [0.002, 0.008, 0.0112]");
  if (p.size() != s.size()) {
    throw_bad("passing", "has " + std::to_string(p.size()) + " values but sieves has " + std::to_string(s.size()) +
                             ": give the % by mass passing each sieve");
  }
  for (std::size_t i = 0; i < s.size(); ++i) {
    const std::string item = "item " + std::to_string(i + 1) + " (" + format_number(s[i]) + " m)";
    if (!(s[i] > 0.0 && s[i] <= 1.0) || !std::isfinite(s[i])) {
      throw_bad("sieves", item + " must be a sieve size in (0, 1] m");
    }
    if (i > 0 && !(s[i] > s[i - 1])) {
      throw_bad("sieves", "must be increasing: " + item + " does not follow " + format_number(s[i - 1]) + " m");
    }
    if (!(p[i] >= 0.0 && p[i] <= 100.0) || !std::isfinite(p[i])) {
      throw_bad("passing", "item " + std::to_string(i + 1) + " is " + format_number(p[i]) +
                               ": a % by mass passing must be in [0, 100]");
    }
    if (i > 0 && p[i] < p[i - 1]) {
      throw_bad("passing", "must not decrease from one sieve to the next (a grading curve is increasing): item " +
                               std::to_string(i + 1) + " is " + format_number(p[i]) + " % at " + format_number(s[i]) +
                               " m after " + format_number(p[i - 1]) + " % at " + format_number(s[i - 1]) + " m");
    }
  }
  if (p.back() != 100.0) {
    throw_bad("passing", "must reach 100 at the largest sieve (" + format_number(s.back()) + " m): the largest stones "
                         "pass it (got " + format_number(p.back()) + ")");
  }
  require_in("binder_content", spec.binder_content, 0.0, true, 100.0, true, "(0, 100) % by mass of the mix");
  require_in("air_voids", spec.air_voids, 0.0, true, 100.0, true, "(0, 100) % by volume of the mix");
  // The largest stone: the first sieve that passes everything.
  std::size_t top = 0;
  while (p[top] < 100.0) ++top;
  if (top == 0) throw_bad("passing", "must be below 100 at the smallest sieve: the grading holds no stones");
  k.dmax = s[top];
  k.dmin = spec.min_chip_size.value_or(std::max(0.002, s.front()));
  if (!(k.dmin >= s.front() && k.dmin < k.dmax) || !std::isfinite(k.dmin)) {
    throw_bad("min_chip_size", "must be at least the smallest sieve, " + format_number(s.front()) +
                                   " m, and below the largest stone, " + format_number(k.dmax) + " m (got " +
                                   format_number(k.dmin) + ")");
  }
  const double fines = passing_at(spec, k.dmin);
  if (!(fines < 1.0)) {
    throw_bad("passing", "must be below 100 at min_chip_size (" + format_number(k.dmin) + " m): the grading holds no stones");
  }
  // The intervals between dmin and dmax, each with the mass the curve gives it.
  RolledMix& mix = k.mix;
  std::vector<double> edges{k.dmin};
  for (double v : s)
    if (v > k.dmin && v < k.dmax) edges.push_back(v);
  edges.push_back(k.dmax);
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    const double lo = edges[i], hi = edges[i + 1];
    const double mass = passing_at(spec, hi) - passing_at(spec, lo);
    RolledMix::Interval in{lo, hi, mass / std::log(hi / lo), 0.0};
    in.number = in.mass_per_log * (std::pow(lo, -3.0) - std::pow(hi, -3.0)) / 3.0;
    total += in.number;
    mix.intervals.push_back(in);
  }
  double sum = 0.0;
  for (const RolledMix::Interval& in : mix.intervals) {
    sum += in.number / total;
    mix.cumulative.push_back(sum);
  }
  mix.cumulative.back() = 1.0;
  // Volumes: the solids share 1 − voids in proportion to their masses over their densities.
  const double binder = spec.binder_content / 100.0;
  const double voids = spec.air_voids / 100.0;
  const double v_aggregate = (1.0 - binder) / aggregate_density;
  const double v_binder = binder / binder_density;
  const double aggregate = (1.0 - voids) * v_aggregate / (v_aggregate + v_binder);
  mix.stones = aggregate * (1.0 - fines);
  mix.mastic = aggregate * fines + (1.0 - voids) * v_binder / (v_aggregate + v_binder);
}

void check_chips(const AggregateRoadSpec& spec, Checked& k) {
  require_in("max_chip_size", spec.max_chip_size, 0.0, true, 1.0, false, "(0, 1] m");
  k.dmax = spec.max_chip_size;
  k.dmin = spec.min_chip_size.value_or(0.25 * k.dmax);
  if (!(k.dmin > 0.0) || !(k.dmin <= k.dmax) || !std::isfinite(k.dmin)) {
    throw_bad("min_chip_size", "must be > 0 and at most max_chip_size, " + format_number(k.dmax) + " m (got " +
                                   format_number(k.dmin) + ")");
  }
  require_in("grading_exponent", spec.grading_exponent, 0.0, true, 2.0, false, "(0, 2]");
  require_in("coverage", spec.coverage, 0.0, true, 1.0, true, "(0, 1) (fraction of the plane covered)");
  require_in("binder_level", spec.binder_level, 0.0, false, 1.0, true, "[0, 1) (fraction of the largest stone's thickness)");
}

// texture = "rolled": the layer, the mastic's share per column and the lowest level it can lie at
// (k.base), from a reference patch of the mix (defined below, with the stones).
void rolled_mastic_share(const AggregateRoadSpec& spec, Checked& k);

Checked check(const AggregateRoadSpec& spec) {
  Checked k;
  if (spec.texture == AggregateRoadSpec::Texture::rolled) {
    check_mix(spec, k);
  } else {
    check_chips(spec, k);
  }
  require_in("shape_factor", spec.shape_factor, 0.0, true, 1.0, false, "(0, 1] (thickness / width)");
  require_in("elongation", spec.elongation, 1.0, false, 4.0, false, "[1, 4] (length / width)");
  require_in("length", spec.length, 0.0, true, std::numeric_limits<double>::max(), false, "(0, inf) m");
  k.spacing = spec.sample_spacing.value_or(spec.texture == AggregateRoadSpec::Texture::rolled
                                               ? std::min(k.dmax / 20.0, k.dmin / 4.0)
                                               : k.dmax / 20.0);
  if (!(k.spacing > 0.0) || !std::isfinite(k.spacing)) {
    throw_bad("sample_spacing", "must be a finite number > 0 (got " + format_number(k.spacing) + ")");
  }
  if (k.spacing > k.dmin / 4.0) {
    throw_bad("sample_spacing", "must be at most min_chip_size / 4 = " + format_number(k.dmin / 4.0) +
                                    " m to resolve the smallest stones (got " + format_number(k.spacing) + ")");
  }
  k.lead_in = spec.lead_in.value_or(4.0 * k.dmax);
  if (!(k.lead_in >= 0.0) || !std::isfinite(k.lead_in)) {
    throw_bad("lead_in", "must be a finite number >= 0 (got " + format_number(k.lead_in) + ")");
  }
  if (spec.texture == AggregateRoadSpec::Texture::rolled) {
    rolled_mastic_share(spec, k);
  } else {
    k.base = spec.binder_level * (spec.shape_factor * k.dmax);
  }
  return k;
}

// One stone of the mix: its footprint's centre, semi-axes a (along its angle) and b, thickness
// semi-axis c, the angle's cosine and sine, and the height of its centre: its upper surface is
// zc + c·sqrt(1 − ρ²).
struct Stone {
  double x, y, a, b, c, cs, sn, zc;
};

// The stones in order of x, to within `bucket` (a stable counting sort: linear in their number).
// Raised in this order the stones sweep the grid row by row instead of jumping over tens of
// megabytes at random: raise_to_stones was bound by cache misses (issue 13's profile put 80 % of
// its time on the store). The surface is a maximum of the stones, the same in any order, bit for bit.
std::vector<Stone> in_order_of_x(const std::vector<Stone>& stones, double x_lo, double x_hi, double bucket) {
  const auto buckets = static_cast<std::size_t>(std::ceil((x_hi - x_lo) / bucket)) + 1;
  const auto bucket_of = [&](const Stone& s) {
    return std::min(buckets - 1, static_cast<std::size_t>(std::max(0.0, (s.x - x_lo) / bucket)));
  };
  std::vector<std::size_t> start(buckets + 1, 0);
  for (const Stone& s : stones) ++start[bucket_of(s) + 1];
  for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
  std::vector<Stone> sorted(stones.size());
  for (const Stone& s : stones) sorted[start[bucket_of(s)]++] = s;
  return sorted;
}

// The stones whose footprints' centres fall in [x_lo, x_hi) × [−y_half, y_half], drawn from
// `engine` until their footprints add up to −ln(1 − coverage) of the area (as a Boolean model of
// that coverage would), four draws per stone in the order x, y, size, angle.
std::vector<Stone> place_chips(const AggregateRoadSpec& spec, const Checked& k, std::mt19937_64& engine, double x_lo,
                               double x_hi, double y_half) {
  const double area = (x_hi - x_lo) * 2.0 * y_half;
  const double footprint_needed = -std::log1p(-spec.coverage) * area;
  const double smallest = std::numbers::pi * spec.elongation * k.dmin * k.dmin / 4.0;
  if (!(footprint_needed / smallest <= max_stones)) {
    throw_bad("length", "the road would hold up to " + format_number(footprint_needed / smallest) +
                            " stones, more than the limit of 2^25; use a shorter length (or width)");
  }
  // Number density of sizes ∝ d^(e-4) on [dmin, dmax], drawn by inverting its distribution.
  const double p = spec.grading_exponent - 3.0;  // in [-3, -1): never 0
  const double lo_p = std::pow(k.dmin, p);
  const double hi_p = std::pow(k.dmax, p);
  std::vector<Stone> stones;
  double footprint = 0.0;
  // Drawing up to 2^25 stones takes seconds: Ctrl-C is polled every 4096 (core/cancellation.hpp).
  const CancellationToken cancel;
  while (footprint < footprint_needed) {
    if (((stones.size() + 1) & 4095u) == 0) cancel.throw_if_cancelled();
    const double x = x_lo + (x_hi - x_lo) * portable::uniform_closed_open(engine);
    const double y = -y_half + 2.0 * y_half * portable::uniform_closed_open(engine);
    const double u = portable::uniform_closed_open(engine);
    const double angle = std::numbers::pi * portable::uniform_closed_open(engine);
    const double d = k.dmin == k.dmax ? k.dmax : std::clamp(std::pow(lo_p + u * (hi_p - lo_p), 1.0 / p), k.dmin, k.dmax);
    const double b = d / 2.0;
    const double a = spec.elongation * b;
    footprint += std::numbers::pi * a * b;
    const double c = spec.shape_factor * b;
    // Positive: resting on z = 0; negative: cut at the top plane z = T.
    const double zc = spec.texture == AggregateRoadSpec::Texture::negative
                          ? spec.shape_factor * k.dmax - (1.0 - negative_cut_fraction) * c
                          : c;
    if (zc + c > k.base) stones.push_back({x, y, a, b, c, std::cos(angle), std::sin(angle), zc});  // else drowned in binder
  }
  return in_order_of_x(stones, x_lo, x_hi, k.spacing);
}

// texture = "rolled": the stones whose centres fall in [x_lo, x_hi) × [−y_half, y_half] ×
// [−depth, 0], drawn from `engine` until their volumes add up to −ln(1 − V_c) of that volume (a
// Boolean model in 3-D of the coarse aggregate's volume fraction), five draws per stone in the
// order x, y, size, angle, depth. The size: an interval of the grading by its number fraction,
// then within it the number density ∝ d^−4 (mass spread evenly in log size) by inversion. A
// stone that would stand above the roller's plane z = 0 is cut flat there (raise_to_stones).
std::vector<Stone> place_mix_stones(const AggregateRoadSpec& spec, const Checked& k, std::mt19937_64& engine,
                                    double x_lo, double x_hi, double y_half) {
  const RolledMix& mix = k.mix;
  const double volume_needed = -std::log1p(-mix.stones) * (x_hi - x_lo) * 2.0 * y_half * mix.depth;
  // The expected number of stones: the volume over the mean stone's, E[d³] = 3·ln(hi/lo)/(lo⁻³ − hi⁻³)
  // within an interval (number density ∝ d⁻⁴); the draws stop within a stone of it.
  double mean_cube = 0.0, fraction_below = 0.0;
  for (std::size_t i = 0; i < mix.intervals.size(); ++i) {
    const RolledMix::Interval& in = mix.intervals[i];
    mean_cube += (mix.cumulative[i] - fraction_below) * 3.0 * std::log(in.hi / in.lo) /
                 (std::pow(in.lo, -3.0) - std::pow(in.hi, -3.0));
    fraction_below = mix.cumulative[i];
  }
  const double expected = volume_needed / (std::numbers::pi / 6.0 * spec.elongation * spec.shape_factor * mean_cube);
  if (!(expected <= max_stones)) {
    throw_bad("length", "the road would hold about " + format_number(expected) +
                            " stones, more than the limit of 2^25; use a shorter length (or width)");
  }
  std::vector<std::array<double, 2>> inverse_cubes;  // lo^-3 and hi^-3 of each interval
  for (const RolledMix::Interval& in : mix.intervals) inverse_cubes.push_back({std::pow(in.lo, -3.0), std::pow(in.hi, -3.0)});
  std::vector<Stone> stones;
  double volume = 0.0;
  const CancellationToken cancel;
  while (volume < volume_needed) {
    if (((stones.size() + 1) & 4095u) == 0) cancel.throw_if_cancelled();
    const double x = x_lo + (x_hi - x_lo) * portable::uniform_closed_open(engine);
    const double y = -y_half + 2.0 * y_half * portable::uniform_closed_open(engine);
    const double u = portable::uniform_closed_open(engine);
    const double angle = std::numbers::pi * portable::uniform_closed_open(engine);
    const double w = portable::uniform_closed_open(engine);
    std::size_t i = 0;
    while (i + 1 < mix.cumulative.size() && u >= mix.cumulative[i]) ++i;
    const double below = i == 0 ? 0.0 : mix.cumulative[i - 1];
    const double v = std::clamp((u - below) / (mix.cumulative[i] - below), 0.0, 1.0);
    const RolledMix::Interval& in = mix.intervals[i];
    const auto [lo3, hi3] = inverse_cubes[i];
    const double d = std::clamp(std::pow(lo3 - v * (lo3 - hi3), -1.0 / 3.0), in.lo, in.hi);
    const double b = d / 2.0;
    const double a = spec.elongation * b;
    const double c = spec.shape_factor * b;
    volume += 4.0 / 3.0 * std::numbers::pi * a * b * c;
    // A stone wholly below the layer the mastic fills is drawn (it fills its volume, and the
    // draws stay in step) but not kept: it neither holds mastic up nor shows.
    const double zc = -mix.depth * w;
    if (zc + c > -mix.thickness) stones.push_back({x, y, a, b, c, std::cos(angle), std::sin(angle), zc});
  }
  return in_order_of_x(stones, x_lo, x_hi, k.spacing);
}

std::vector<Stone> place_stones(const AggregateRoadSpec& spec, const Checked& k, std::mt19937_64& engine, double x_lo,
                                double x_hi, double y_half) {
  return spec.texture == AggregateRoadSpec::Texture::rolled ? place_mix_stones(spec, k, engine, x_lo, x_hi, y_half)
                                                            : place_chips(spec, k, engine, x_lo, x_hi, y_half);
}

// The columns of a grid y = (j − half_y) h that are held: j = first .. first + count − 1.
struct Columns {
  std::size_t first = 0, count = 0;
  static Columns all(std::size_t half_y) { return {0, 2 * half_y + 1}; }
};

// Raises the grid x = (first + i) h (i < x_count), y = (j − half_y) h (j in `held`), row-major
// in x (row stride held.count), to the upper surface of each stone over it. The maximum does not
// depend on the order of the stones, and a point's height on the stones over it only.
void raise_to_stones(const AggregateRoadSpec& spec, const Checked& k, const std::vector<Stone>& stones,
                     std::size_t first, std::size_t x_count, std::size_t half_y, Columns held, std::vector<double>& z) {
  const double h = k.spacing;
  const std::size_t y_count = held.count;
  // The plane the stones are cut flat at: the top plane z = T of the negative texture, the
  // roller's plane z = 0 of the rolled mix; none for the positive texture.
  const double ceiling = spec.texture == AggregateRoadSpec::Texture::negative ? spec.shape_factor * k.dmax
                         : spec.texture == AggregateRoadSpec::Texture::rolled ? 0.0
                                                                              : std::numeric_limits<double>::infinity();
  const double origin = h * static_cast<double>(first);
  // Raising the grid to up to 2^25 stones takes tens of seconds: polled every 4096 stones too.
  const CancellationToken cancel;
  std::size_t raised = 0;
  double* const heights = z.data();  // held in a register: the store below would reload z's pointer
  for (const Stone& s : stones) {
    if ((++raised & 4095u) == 0) cancel.throw_if_cancelled();
    // Hidden under the lowest surface the mastic can have (rolled; the chips' are never kept).
    if (s.zc + s.c <= k.base) continue;
    const double x = s.x - origin, y = s.y, a = s.a, b = s.b, c = s.c, cs = s.cs, sn = s.sn;
    // Upper surface z_c + c sqrt(1 - rho^2) (rho the normalised footprint radius); negative: cut
    // at the top plane z = T.
    const double z_c = s.zc;
    const double i_lo = std::max(0.0, std::ceil((x - a) / h));
    const double i_hi = std::min(static_cast<double>(x_count - 1), std::floor((x + a) / h));
    const double j_lo = std::max(static_cast<double>(held.first), std::ceil((y - a) / h + static_cast<double>(half_y)));
    const double j_hi = std::min(static_cast<double>(held.first + held.count - 1),
                                 std::floor((y + a) / h + static_cast<double>(half_y)));
    if (i_lo > i_hi || j_lo > j_hi) continue;
    const auto j_first = static_cast<std::size_t>(j_lo), j_last = static_cast<std::size_t>(j_hi);
    for (auto i = static_cast<std::size_t>(i_lo); i <= static_cast<std::size_t>(i_hi); ++i) {
      const double dx = h * static_cast<double>(i) - x;
      const double dx_cs = dx * cs, dx_sn = -dx * sn;
      double* row = heights + i * y_count;  // cell j at row[j − held.first]
      auto j = j_first;
#if defined(__SSE2__)
      // Two cells a time, each by the scalar loop's operations in its order (IEEE division and
      // square root: the same bits); a cell outside the footprint keeps its height (its lane's
      // root, of a negative number, is not used).
      const __m128d v_dx_cs = _mm_set1_pd(dx_cs), v_dx_sn = _mm_set1_pd(dx_sn), v_sn = _mm_set1_pd(sn),
                    v_cs = _mm_set1_pd(cs), v_a = _mm_set1_pd(a), v_b = _mm_set1_pd(b), v_h = _mm_set1_pd(h),
                    v_y = _mm_set1_pd(y), v_c = _mm_set1_pd(c), v_zc = _mm_set1_pd(z_c),
                    v_one = _mm_set1_pd(1.0), v_t = _mm_set1_pd(ceiling),
                    v_half = _mm_set1_pd(static_cast<double>(half_y));
      for (; j + 1 <= j_last; j += 2) {
        const __m128d v_j = _mm_set_pd(static_cast<double>(j + 1), static_cast<double>(j));
        const __m128d dy = _mm_sub_pd(_mm_mul_pd(v_h, _mm_sub_pd(v_j, v_half)), v_y);
        const __m128d along = _mm_div_pd(_mm_add_pd(v_dx_cs, _mm_mul_pd(dy, v_sn)), v_a);
        const __m128d across = _mm_div_pd(_mm_add_pd(v_dx_sn, _mm_mul_pd(dy, v_cs)), v_b);
        const __m128d rho2 = _mm_add_pd(_mm_mul_pd(along, along), _mm_mul_pd(across, across));
        __m128d top = _mm_add_pd(v_zc, _mm_mul_pd(v_c, _mm_sqrt_pd(_mm_sub_pd(v_one, rho2))));
        top = _mm_min_pd(top, v_t);
        double* cells = row + (j - held.first);
        const __m128d cell = _mm_loadu_pd(cells);
        const __m128d inside = _mm_cmplt_pd(rho2, v_one);
        const __m128d higher = _mm_max_pd(cell, top);
        _mm_storeu_pd(cells, _mm_or_pd(_mm_and_pd(inside, higher), _mm_andnot_pd(inside, cell)));
      }
#endif
      for (; j <= j_last; ++j) {
        const double dy = h * (static_cast<double>(j) - static_cast<double>(half_y)) - y;
        const double along = (dx_cs + dy * sn) / a;
        const double across = (dx_sn + dy * cs) / b;
        const double rho2 = along * along + across * across;
        if (rho2 >= 1.0) continue;
        double top = z_c + c * std::sqrt(1.0 - rho2);
        top = std::min(top, ceiling);
        double& cell = row[j - held.first];
        cell = std::max(cell, top);
      }
    }
  }
}

double reach_of(const AggregateRoadSpec& spec, const Checked& k) { return spec.elongation * k.dmax / 2.0; }  // largest semi-axis

// How far beyond a grid the stones must be known: the rolled mix's mastic surface is averaged
// over k.mix.smoothing samples either side.
double margin_of(const Checked& k) { return k.spacing * static_cast<double>(k.mix.smoothing); }

// texture = "rolled": ORs into occupied[i·ny + j] the levels of the layer (rolled_mastic.hpp)
// each stone of `stones` fills in the column x = h·(x_first + i), y = h·(y_first + j).
void mark_stone_levels(const Checked& k, std::span<const Stone> stones, long x_first, std::size_t nx, long y_first,
                       std::size_t ny, std::vector<std::uint64_t>& occupied) {
  const double h = k.spacing, thickness = k.mix.thickness;
  const double x0 = h * static_cast<double>(x_first), y0 = h * static_cast<double>(y_first);
  const CancellationToken cancel;
  std::size_t marked = 0;
  for (const Stone& s : stones) {
    if ((++marked & 4095u) == 0) cancel.throw_if_cancelled();
    const double x = s.x - x0, y = s.y - y0;
    const double i_lo = std::max(0.0, std::ceil((x - s.a) / h));
    const double i_hi = std::min(static_cast<double>(nx - 1), std::floor((x + s.a) / h));
    if (i_lo > i_hi) continue;
    // ρ² = (dx·cs + dy·sn)²/a² + (dy·cs − dx·sn)²/b² = A·dy² + B·dy + C: the chord of the
    // footprint on each row (a sample wider either side; the test on ρ² decides).
    const double ia = 1.0 / s.a, ib = 1.0 / s.b, ia2 = ia * ia, ib2 = ib * ib;
    const double quad = s.sn * s.sn * ia2 + s.cs * s.cs * ib2;
    const double cs_a = s.cs * ia, sn_a = s.sn * ia, cs_b = s.cs * ib, sn_b = s.sn * ib;
    for (auto i = static_cast<std::size_t>(i_lo); i <= static_cast<std::size_t>(i_hi); ++i) {
      const double dx = h * static_cast<double>(i) - x;
      const double lin = 2.0 * dx * s.cs * s.sn * (ia2 - ib2);
      const double cst = dx * dx * (s.cs * s.cs * ia2 + s.sn * s.sn * ib2) - 1.0;
      const double disc = lin * lin - 4.0 * quad * cst;
      if (disc < 0.0) continue;
      const double root = std::sqrt(disc);
      const double j_lo = std::max(0.0, std::ceil((y + (-lin - root) / (2.0 * quad)) / h) - 1.0);
      const double j_hi = std::min(static_cast<double>(ny - 1), std::floor((y + (-lin + root) / (2.0 * quad)) / h) + 1.0);
      if (j_lo > j_hi) continue;
      for (auto j = static_cast<std::size_t>(j_lo); j <= static_cast<std::size_t>(j_hi); ++j) {
        const double dy = h * static_cast<double>(j) - y;
        const double along = dx * cs_a + dy * sn_a;
        const double across = dy * cs_b - dx * sn_b;
        const double rho2 = along * along + across * across;
        if (rho2 >= 1.0) continue;
        const double half = s.c * std::sqrt(1.0 - rho2);
        occupied[i * ny + j] |= occupied_levels(s.zc - half, std::min(s.zc + half, 0.0), thickness);
      }
    }
  }
}

// The stones of a set (in order of x to within k.spacing: in_order_of_x) that can reach
// x in [x_lo, x_hi), from `start` on; `start` moves past those that lie before x_lo for good
// (the next call asks for a later stretch).
std::span<const Stone> stones_reaching(const std::vector<Stone>& stones, std::size_t& start, double x_lo, double x_hi,
                                       double reach, double spacing) {
  while (start < stones.size() && stones[start].x + reach < x_lo) ++start;
  std::size_t end = start;
  // A stone after one centred at x lies at x − spacing or beyond.
  while (end < stones.size() && stones[end].x - reach - spacing < x_hi) ++end;
  return {stones.data() + start, end - start};
}

// texture = "rolled": the mastic's surface (m, rolled_mastic.hpp) over the grid
// x = (first + i)·h (i < x_count), y = (j − half_y)·h (j in `held`), row-major in x, from the
// stones of `sets` (none with a semi-axis beyond `reach`). The grid is averaged with the samples up to k.mix.smoothing beyond it, whose
// stones `sets` must hold; `beyond_end` false: the road ends at the grid's last line, and the
// average is clipped there. Made in stretches of mastic_rows rows along x, each with the rows its
// averages reach either side: the memory of one stretch, and the same bits as the whole grid at
// once (smooth_mastic_surface's sums are exact).
std::vector<double> mastic_surface(const Checked& k, double reach, const std::vector<const std::vector<Stone>*>& sets,
                                   std::size_t first, std::size_t x_count, std::size_t half_y, Columns held,
                                   bool beyond_end) {
  constexpr std::size_t mastic_rows = 512;
  const auto r = static_cast<long>(k.mix.smoothing);
  const long y_first = static_cast<long>(held.first) - static_cast<long>(half_y) - r;
  const std::size_t ny = held.count + 2 * k.mix.smoothing;
  const long last_row = static_cast<long>(x_count) - 1 + (beyond_end ? r : 0);  // the last row with stones known
  const double h = k.spacing, dz = k.mix.thickness / mastic_levels;
  std::vector<double> z(x_count * held.count);
  std::vector<std::size_t> starts(sets.size(), 0);
  std::vector<std::uint64_t> occupied;
  std::vector<double> level;
  for (std::size_t out = 0; out < x_count; out += mastic_rows) {
    const std::size_t out_end = std::min(x_count, out + mastic_rows);
    const long lo = static_cast<long>(out) - r, hi = std::min(static_cast<long>(out_end) - 1 + r, last_row);
    const auto rows = static_cast<std::size_t>(hi - lo + 1);
    const long x_first = static_cast<long>(first) + lo;
    occupied.assign(rows * ny, 0);
    for (std::size_t set = 0; set < sets.size(); ++set) {
      const std::span<const Stone> near =
          stones_reaching(*sets[set], starts[set], h * static_cast<double>(x_first),
                          h * static_cast<double>(x_first + static_cast<long>(rows)), reach, h);
      mark_stone_levels(k, near, x_first, rows, y_first, ny, occupied);
    }
    level.resize(rows * ny);
    for (std::size_t c = 0; c < level.size(); ++c) level[c] = mastic_top(occupied[c], k.mix.share);
    smooth_mastic_surface(level, rows, ny, k.mix.smoothing);
    for (std::size_t i = out; i < out_end; ++i)
      for (std::size_t j = 0; j < held.count; ++j)
        z[i * held.count + j] = -k.mix.thickness + dz * level[(i - out + k.mix.smoothing) * ny + j + k.mix.smoothing];
  }
  return z;
}

// The flat level, or the rolled mix's mastic surface, of a grid as mastic_surface's, before the
// stones are raised on it.
std::vector<double> floor_heights(const AggregateRoadSpec& spec, const Checked& k,
                                  const std::vector<const std::vector<Stone>*>& sets, std::size_t first,
                                  std::size_t x_count, std::size_t half_y, Columns held, bool beyond_end) {
  if (spec.texture != AggregateRoadSpec::Texture::rolled) return std::vector<double>(x_count * held.count, k.base);
  return mastic_surface(k, reach_of(spec, k), sets, first, x_count, half_y, held, beyond_end);
}

void rolled_mastic_share(const AggregateRoadSpec& spec, Checked& k) {
  RolledMix& mix = k.mix;
  mix.thickness = spec.shape_factor * k.dmax;                  // T
  mix.depth = mix.thickness + spec.shape_factor * k.dmax / 2.0;  // T + c of the largest stone
  // The mastic levels out within a pocket between the stones, as wide as the largest of them.
  mix.smoothing = static_cast<std::size_t>(std::lround(k.dmax / 2.0 / k.spacing));
  k.base = -mix.thickness;  // every stone of the layer, for the reference patch
  // The reference patch: its columns' free levels give the offset that keeps the mastic's total
  // when the crowded columns are filled to the plane.
  const double side = std::max(0.1, reference_patch_stones * k.dmax);
  const std::size_t n = static_cast<std::size_t>(std::ceil(side / k.spacing)) + 1;
  const double reach = reach_of(spec, k);
  std::mt19937_64 engine(reference_patch_seed);
  const std::vector<Stone> stones = place_stones(spec, k, engine, -reach, side + reach, side / 2.0 + reach);
  std::vector<std::uint64_t> occupied(n * n, 0);
  mark_stone_levels(k, std::span<const Stone>(stones), 0, n, -static_cast<long>(n / 2), n, occupied);
  const double share = mix.mastic * mastic_levels;
  try {
    mix.share = share + mastic_offset(occupied, share);
  } catch (const std::invalid_argument&) {
    throw_bad("air_voids", "leaves the mix's mastic more volume than the pore space between its stones: with " +
                               format_number(spec.binder_content) + " % binder the stones and mastic fill more than the "
                               "layer; check binder_content, air_voids and the grading");
  }
  k.base = -mix.thickness + mix.thickness / mastic_levels * std::min(mix.share, static_cast<double>(mastic_levels));
}

// The visible upper surface over the grid x = i h (i < x_count), y = (j - half_y) h
// (j < 2 half_y + 1), row-major in x, before its mean is removed: the stones of the whole grid
// (centres within a stone's reach of it) from the spec's seed. `mean` receives its mean.
std::vector<double> raw_heights(const AggregateRoadSpec& spec, const Checked& k, std::size_t x_count,
                                std::size_t half_y, double& mean) {
  const double h = k.spacing;
  const double reach = reach_of(spec, k), margin = margin_of(k);
  std::mt19937_64 engine(spec.seed);
  const std::vector<Stone> stones = place_stones(spec, k, engine, -reach - margin, h * static_cast<double>(x_count - 1) + reach,
                                                 h * static_cast<double>(half_y) + reach + margin);
  std::vector<double> z = floor_heights(spec, k, {&stones}, 0, x_count, half_y, Columns::all(half_y), false);
  raise_to_stones(spec, k, stones, 0, x_count, half_y, Columns::all(half_y), z);
  mean = 0.0;
  for (double v : z) mean += v;
  mean /= static_cast<double>(z.size());
  return z;
}

// Removes `mean` and applies the lead-in window (x = (first + i) h).
void remove_mean(const Checked& k, double mean, std::size_t first, std::size_t y_count, std::vector<double>& z) {
  const std::size_t x_count = z.size() / y_count;
  for (std::size_t i = 0; i < x_count; ++i) {
    const double w = lead_in_window(k.spacing * static_cast<double>(first + i), k.lead_in);
    for (std::size_t j = 0; j < y_count; ++j) z[i * y_count + j] = w * (z[i * y_count + j] - mean);
  }
}

// The visible upper surface over the grid x = i h (i < x_count), y = (j - half_y) h
// (j < 2 half_y + 1), mean removed and lead-in window applied, row-major in x.
std::vector<double> build_heights(const AggregateRoadSpec& spec, const Checked& k, std::size_t x_count,
                                  std::size_t half_y) {
  double mean = 0.0;
  std::vector<double> z = raw_heights(spec, k, x_count, half_y, mean);
  remove_mean(k, mean, 0, 2 * half_y + 1, z);
  return z;
}

std::size_t points_to(double extent, double spacing, const char* key) {
  const double last = std::max(1.0, std::ceil(extent / spacing));
  if (!(last <= static_cast<double>(max_synthesis_points))) {
    throw_bad(key, "the road needs " + format_number(last) +
                       " samples along one axis, more than the limit of 2^26; use a larger sample_spacing");
  }
  return static_cast<std::size_t>(last);
}

}  // namespace

namespace {

// A TOML list of numbers (integers or floats), required.
std::vector<double> read_numbers(const ConfigTable& road, const char* key, const std::string& what) {
  const toml::node* node = road.raw(key);
  if (node == nullptr) road.fail(key, "is required for texture = \"rolled\": " + what);
  const toml::array* list = node->as_array();
  if (list == nullptr) road.fail(key, "must be a list of numbers: " + what);
  std::vector<double> values;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::node& item = *list->get(i);
    if (const auto* f = item.as_floating_point()) {
      values.push_back(f->get());
    } else if (const auto* n = item.as_integer()) {
      values.push_back(static_cast<double>(n->get()));
    } else {
      road.fail(key, "item " + std::to_string(i + 1) + " is not a number: " + what);
    }
  }
  return values;
}

}  // namespace

void read_aggregate_keys(const ConfigTable& road, AggregateRoadSpec& spec, bool surface, double default_length) {
  const std::string texture = road.choice("texture", {"positive", "negative", "rolled"}, "positive");
  spec.texture = texture == "rolled"     ? AggregateRoadSpec::Texture::rolled
                 : texture == "negative" ? AggregateRoadSpec::Texture::negative
                                         : AggregateRoadSpec::Texture::positive;
  if (spec.texture == AggregateRoadSpec::Texture::rolled) {
    // The mix design; the stones' largest size, grading, density and the mastic's level follow.
    spec.sieves = read_numbers(road, "sieves", "the sieve sizes of the grading in m, increasing");
    spec.passing = read_numbers(road, "passing", "the % by mass passing each sieve");
    spec.binder_content = road.number("binder_content");
    spec.air_voids = road.number("air_voids");
  } else {
    spec.max_chip_size = road.positive("max_chip_size");
    spec.grading_exponent = road.positive("grading_exponent", spec.grading_exponent);
    spec.coverage = road.positive("coverage", spec.coverage);
    spec.binder_level = road.non_negative("binder_level", spec.binder_level);
  }
  if (road.contains("min_chip_size")) spec.min_chip_size = road.positive("min_chip_size");
  spec.shape_factor = road.positive("shape_factor", spec.shape_factor);
  spec.elongation = road.positive("elongation", spec.elongation);
  spec.seed = static_cast<std::uint64_t>(road.integer("seed", 1, 0, std::numeric_limits<std::int64_t>::max()));
  spec.length = road.positive("length", default_length);
  if (surface) spec.width = road.positive("width", 0.5);
  if (road.contains("sample_spacing")) spec.sample_spacing = road.positive("sample_spacing");
  if (road.contains("lead_in")) spec.lead_in = road.non_negative("lead_in");
}

std::unique_ptr<SampledProfile> make_aggregate_profile(const AggregateRoadSpec& spec) {
  if (!std::isfinite(spec.x_max)) throw std::invalid_argument("make_aggregate_profile: x_max must be finite");
  const Checked k = check(spec);
  const std::size_t last = points_to(std::max(spec.length, spec.x_max), k.spacing, "sample_spacing");
  // The line y = 0 of a map: only the stones that can reach it are placed (a strip of the
  // largest stone's reach either side), at the same density.
  std::vector<double> z = build_heights(spec, k, last + 1, 0);
  return std::make_unique<SampledProfile>("aggregate", k.spacing, std::move(z));
}

namespace {

// The grid of a surface up to max(length, x_max): the last sample index along x and half_y;
// every size checked.
struct SurfaceGrid {
  std::size_t last = 0, half_y = 0;
};

SurfaceGrid surface_grid(const AggregateRoadSpec& spec, const Checked& k) {
  if (!std::isfinite(spec.x_max)) throw std::invalid_argument("make_aggregate_surface: x_max must be finite");
  if (!(spec.half_width >= 0.0) || !std::isfinite(spec.half_width)) {
    throw std::invalid_argument("make_aggregate_surface: half_width must be finite and >= 0");
  }
  require_in("width", spec.width, 0.0, true, std::numeric_limits<double>::max(), false, "(0, inf) m");
  if (spec.half_width > spec.width / 2.0) {
    throw_bad("width", "the surface is " + format_number(spec.width) +
                           " m wide (y from -width/2 to width/2), but the tyre's contact grid reaches |y| = " +
                           format_number(spec.half_width) + " m; set width to at least " +
                           format_number(2.0 * spec.half_width) + " m");
  }
  SurfaceGrid g;
  g.last = points_to(std::max(spec.length, spec.x_max), k.spacing, "sample_spacing");
  g.half_y = points_to(spec.width / 2.0, k.spacing, "sample_spacing");
  const double points = static_cast<double>(g.last + 1) * static_cast<double>(2 * g.half_y + 1);
  if (points > static_cast<double>(max_synthesis_points)) {
    throw_bad("sample_spacing", "the surface needs " + format_number(points) +
                                    " samples, more than the limit of 2^26; use a larger sample_spacing, a "
                                    "shorter length or a smaller width");
  }
  return g;
}

}  // namespace

std::unique_ptr<SampledSurface> make_aggregate_surface(const AggregateRoadSpec& spec) {
  const Checked k = check(spec);
  const SurfaceGrid g = surface_grid(spec, k);
  std::vector<double> z = build_heights(spec, k, g.last + 1, g.half_y);
  return std::make_unique<SampledSurface>("aggregate", k.spacing, g.last + 1, 2 * g.half_y + 1, std::move(z));
}

namespace {

// See make_rolling_aggregate_surface.
class TiledAggregateSurface final : public RoadSurface {
 public:
  TiledAggregateSurface(const AggregateRoadSpec& spec, std::size_t tile_samples, std::size_t half_y)
      : spec_(spec), k_(check(spec)), tile_samples_(tile_samples), half_y_(half_y) {
    // Tile 0: the road make_aggregate_surface makes for `length`, and the mean every tile removes
    // (the rolled mix's mastic surface, averaged across the tile's end, only differs from that
    // road's, which ends there, within its averaging radius of the end).
    std::vector<double> z = raw_tile(0);
    mean_ = 0.0;
    for (double v : z) mean_ += v;
    mean_ /= static_cast<double>(z.size());
    remove_mean(k_, mean_, 0, 2 * half_y_ + 1, z);
    tiles_[0] = {0, Columns::all(half_y_), std::move(z)};
    tiles_[1] = {std::numeric_limits<std::size_t>::max(), {}, {}};
    // The later tiles only under the tyre: |y| ≤ half_width and a column beyond for the
    // interpolation, and one more for rounding (a third of the surface's 0.5 m, and of the time).
    const auto reach = static_cast<std::size_t>(std::ceil(spec_.half_width / k_.spacing)) + 2;
    const std::size_t strip = std::min(half_y_, reach);
    strip_ = {half_y_ - strip, 2 * strip + 1};
    make_ahead(1);
  }

  std::string type() const override { return "aggregate"; }

  double height(double x, double y) const override {
    if (x < 0.0) return 0.0;
    const double tile_length = k_.spacing * static_cast<double>(tile_samples_);
    // The tile whose stretch holds x; its grid ends on the next tile's first line, so a point
    // on a boundary is interpolated within either.
    auto index = static_cast<std::size_t>(std::floor(x / tile_length));
    if (index > 0 && x - tile_length * static_cast<double>(index) < 0.0) --index;
    const std::lock_guard lock(mutex_);
    const Tile& t = tile(index);
    return grid_height(t.heights.data(), t.held.count, tile_samples_ + 1, 2 * half_y_ + 1, k_.spacing,
                       x - tile_length * static_cast<double>(index), y, "aggregate", t.held.first, t.held.count);
  }

 private:
  struct Tile {
    std::size_t index;
    Columns held;
    std::vector<double> heights;
  };

  // The stones of tile `index`, drawn once: a tile is raised by the stones of its neighbours too,
  // so the three sets in use are kept (the tyre moves on to the next tile, sharing two of them).
  const std::vector<Stone>& stones_of(std::size_t index) const {
    for (TileStones& t : stones_) {
      if (t.index != index) continue;
      t.last_use = ++uses_;
      return t.stones;
    }
    TileStones& slot = *std::min_element(stones_.begin(), stones_.end(), [](const TileStones& l, const TileStones& r) {
      return l.last_use < r.last_use;
    });
    slot = {index, ++uses_, draw_stones(index)};
    return slot.stones;
  }

  // The stones centred in tile k's stretch: tile 0's are those make_aggregate_surface places
  // (centres in [−reach, L + reach)); tile k ≥ 1's are centred in [kL + reach, (k+1)L + reach).
  std::vector<Stone> draw_stones(std::size_t index) const {
    const double h = k_.spacing, reach = reach_of(spec_, k_), margin = margin_of(k_);
    const double length = h * static_cast<double>(tile_samples_);
    const double y_half = h * static_cast<double>(half_y_) + reach + margin;
    if (index == 0) {
      std::mt19937_64 engine(spec_.seed);
      return place_stones(spec_, k_, engine, -reach - margin, length + reach, y_half);
    }
    std::seed_seq seeds{static_cast<std::uint32_t>(spec_.seed), static_cast<std::uint32_t>(spec_.seed >> 32),
                        static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(index >> 32)};
    std::mt19937_64 engine(seeds);
    const double start = length * static_cast<double>(index) + reach;
    return place_stones(spec_, k_, engine, start, start + length, y_half);
  }

  // Tile `index`, from the two held, from the one made ahead, or made now; the next one is then
  // made ahead on another thread (called under mutex_).
  const Tile& tile(std::size_t index) const {
    for (const Tile& t : tiles_)
      if (t.index == index) return t;
    // Replace the tile farther from this one (an empty slot first): the tyre reads two
    // neighbouring tiles around a boundary, and moves on.
    const auto distance = [index](const Tile& t) {
      if (t.index == std::numeric_limits<std::size_t>::max()) return std::numeric_limits<std::size_t>::max();
      return t.index > index ? t.index - index : index - t.index;
    };
    Tile& slot = distance(tiles_[0]) >= distance(tiles_[1]) ? tiles_[0] : tiles_[1];
    // One tile is made at a time (the stones' cache is the maker's): a tile made ahead is
    // finished, and taken if it is this one, before another is begun.
    std::optional<Tile> ahead;
    if (ahead_.valid()) ahead = ahead_.get();
    slot = ahead && ahead->index == index ? std::move(*ahead) : make_tile(index);
    // The tyre reaches the next tile 5 m on (0.2 s at 80 km/h), and it takes about a tenth of
    // that to make: made beside the contact loop, on the core it leaves idle. A tile is a
    // function of its index alone, so the heights do not depend on which thread made it.
    make_ahead(index + 1);
    return slot;
  }

  // Begins tile `index` on another thread, unless the run never reaches it.
  void make_ahead(std::size_t index) const {
    if (k_.spacing * static_cast<double>(tile_samples_ * index) > spec_.x_max) return;
    ahead_ = std::async(std::launch::async, [this, index] { return make_tile(index); });
  }

  Tile make_tile(std::size_t index) const {
    const Columns held = index == 0 ? Columns::all(half_y_) : strip_;
    std::vector<double> z = raw_tile(index);
    remove_mean(k_, mean_, index * tile_samples_, held.count, z);
    return {index, held, std::move(z)};
  }

  // Tile `index`'s heights before the mean is removed: raised by its own stones and its
  // neighbours' (those of the tile after it reach none of its points, but the rolled mix's
  // mastic surface is averaged across its end).
  std::vector<double> raw_tile(std::size_t index) const {
    const Columns held = index == 0 ? Columns::all(half_y_) : strip_;
    const std::size_t first = index * tile_samples_;
    std::vector<const std::vector<Stone>*> sets;
    for (std::size_t neighbour = index == 0 ? 0 : index - 1; neighbour <= index + 1; ++neighbour)
      sets.push_back(&stones_of(neighbour));
    std::vector<double> z = floor_heights(spec_, k_, sets, first, tile_samples_ + 1, half_y_, held, true);
    for (const std::vector<Stone>* stones : sets) raise_to_stones(spec_, k_, *stones, first, tile_samples_ + 1, half_y_, held, z);
    return z;
  }

  struct TileStones {
    std::size_t index = std::numeric_limits<std::size_t>::max();
    std::uint64_t last_use = 0;
    std::vector<Stone> stones;
  };

  AggregateRoadSpec spec_;
  Checked k_;
  std::size_t tile_samples_, half_y_;
  double mean_ = 0.0;
  Columns strip_;  // the columns of tiles k ≥ 1
  mutable std::array<TileStones, 3> stones_;
  mutable std::uint64_t uses_ = 0;
  // A cache behind a const interface (RoadSurface::height): the two tiles nearest the tyre.
  mutable std::array<Tile, 2> tiles_;
  mutable std::mutex mutex_;
  // The next tile, being made ahead. Last, so that it is destroyed first: its destructor waits
  // for the maker, which reads the members above.
  mutable std::future<Tile> ahead_;
};

}  // namespace

std::unique_ptr<RoadSurface> make_rolling_aggregate_surface(const AggregateRoadSpec& spec) {
  if (!std::isfinite(spec.x_max)) throw std::invalid_argument("make_rolling_aggregate_surface: x_max must be finite");
  if (!(spec.x_max > spec.length)) return make_aggregate_surface(spec);
  // Every key and size is checked for one tile: the run's length costs no memory.
  AggregateRoadSpec tile = spec;
  tile.x_max = spec.length;
  const SurfaceGrid g = surface_grid(tile, check(tile));
  return std::make_unique<TiledAggregateSurface>(spec, g.last, g.half_y);
}

}  // namespace rollnoise
