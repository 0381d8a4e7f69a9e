#include "road/aggregate_road.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "road/portable_normal.hpp"
#include "road/spectral_synthesis.hpp"

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

struct Checked {
  double dmax = 0.0, dmin = 0.0, spacing = 0.0, lead_in = 0.0;
};

Checked check(const AggregateRoadSpec& spec) {
  Checked k;
  require_in("max_chip_size", spec.max_chip_size, 0.0, true, 1.0, false, "(0, 1] m");
  k.dmax = spec.max_chip_size;
  k.dmin = spec.min_chip_size.value_or(0.25 * k.dmax);
  if (!(k.dmin > 0.0) || !(k.dmin <= k.dmax) || !std::isfinite(k.dmin)) {
    throw_bad("min_chip_size", "must be > 0 and at most max_chip_size, " + format_number(k.dmax) + " m (got " +
                                   format_number(k.dmin) + ")");
  }
  require_in("grading_exponent", spec.grading_exponent, 0.0, true, 2.0, false, "(0, 2]");
  require_in("shape_factor", spec.shape_factor, 0.0, true, 1.0, false, "(0, 1] (thickness / width)");
  require_in("elongation", spec.elongation, 1.0, false, 4.0, false, "[1, 4] (length / width)");
  require_in("coverage", spec.coverage, 0.0, true, 1.0, true, "(0, 1) (fraction of the plane covered)");
  require_in("binder_level", spec.binder_level, 0.0, false, 1.0, true, "[0, 1) (fraction of the largest stone's thickness)");
  require_in("length", spec.length, 0.0, true, std::numeric_limits<double>::max(), false, "(0, inf) m");
  k.spacing = spec.sample_spacing.value_or(k.dmax / 20.0);
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
  return k;
}

// The visible upper surface over the grid x = i h (i < x_count), y = (j - half_y) h
// (j < 2 half_y + 1), mean removed and lead-in window applied, row-major in x.
std::vector<double> build_heights(const AggregateRoadSpec& spec, const Checked& k, std::size_t x_count,
                                  std::size_t half_y) {
  const double h = k.spacing;
  const std::size_t y_count = 2 * half_y + 1;
  const double reach = spec.elongation * k.dmax / 2.0;  // largest semi-axis
  const double x_lo = -reach;
  const double x_hi = h * static_cast<double>(x_count - 1) + reach;
  const double y_half = h * static_cast<double>(half_y) + reach;
  const double area = (x_hi - x_lo) * 2.0 * y_half;
  const double footprint_needed = -std::log1p(-spec.coverage) * area;
  const double smallest = std::numbers::pi * spec.elongation * k.dmin * k.dmin / 4.0;
  if (!(footprint_needed / smallest <= max_stones)) {
    throw_bad("length", "the road would hold up to " + format_number(footprint_needed / smallest) +
                            " stones, more than the limit of 2^25; use a shorter length (or width)");
  }

  const double thickness = spec.shape_factor * k.dmax;  // T
  const double binder = spec.binder_level * thickness;
  const bool negative = spec.texture == AggregateRoadSpec::Texture::negative;
  std::vector<double> z(x_count * y_count, binder);

  // Number density of sizes ∝ d^(e-4) on [dmin, dmax], drawn by inverting its distribution.
  const double p = spec.grading_exponent - 3.0;  // in [-3, -1): never 0
  const double lo_p = std::pow(k.dmin, p);
  const double hi_p = std::pow(k.dmax, p);

  std::mt19937_64 engine(spec.seed);
  double footprint = 0.0;
  while (footprint < footprint_needed) {
    // Four draws per stone, in this order: x, y, size, angle.
    const double x = x_lo + (x_hi - x_lo) * portable::uniform_closed_open(engine);
    const double y = -y_half + 2.0 * y_half * portable::uniform_closed_open(engine);
    const double u = portable::uniform_closed_open(engine);
    const double angle = std::numbers::pi * portable::uniform_closed_open(engine);
    const double d = k.dmin == k.dmax ? k.dmax : std::clamp(std::pow(lo_p + u * (hi_p - lo_p), 1.0 / p), k.dmin, k.dmax);
    const double b = d / 2.0;
    const double a = spec.elongation * b;
    const double c = spec.shape_factor * b;
    footprint += std::numbers::pi * a * b;
    // Upper surface z_c + c sqrt(1 - rho^2) (rho the normalised footprint radius); positive:
    // resting on z = 0; negative: cut at the top plane z = T.
    const double z_c = negative ? thickness - (1.0 - negative_cut_fraction) * c : c;
    const double cs = std::cos(angle);
    const double sn = std::sin(angle);
    const double i_lo = std::max(0.0, std::ceil((x - a) / h));
    const double i_hi = std::min(static_cast<double>(x_count - 1), std::floor((x + a) / h));
    const double j_lo = std::max(0.0, std::ceil((y - a) / h + static_cast<double>(half_y)));
    const double j_hi = std::min(static_cast<double>(y_count - 1), std::floor((y + a) / h + static_cast<double>(half_y)));
    if (i_lo > i_hi || j_lo > j_hi) continue;
    for (auto i = static_cast<std::size_t>(i_lo); i <= static_cast<std::size_t>(i_hi); ++i) {
      const double dx = h * static_cast<double>(i) - x;
      for (auto j = static_cast<std::size_t>(j_lo); j <= static_cast<std::size_t>(j_hi); ++j) {
        const double dy = h * (static_cast<double>(j) - static_cast<double>(half_y)) - y;
        const double along = (dx * cs + dy * sn) / a;
        const double across = (-dx * sn + dy * cs) / b;
        const double rho2 = along * along + across * across;
        if (rho2 >= 1.0) continue;
        double top = z_c + c * std::sqrt(1.0 - rho2);
        if (negative) top = std::min(top, thickness);
        double& cell = z[i * y_count + j];
        cell = std::max(cell, top);
      }
    }
  }

  double mean = 0.0;
  for (double v : z) mean += v;
  mean /= static_cast<double>(z.size());
  for (std::size_t i = 0; i < x_count; ++i) {
    const double w = lead_in_window(h * static_cast<double>(i), k.lead_in);
    for (std::size_t j = 0; j < y_count; ++j) z[i * y_count + j] = w * (z[i * y_count + j] - mean);
  }
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

void read_aggregate_keys(const ConfigTable& road, AggregateRoadSpec& spec, bool surface, double default_length) {
  spec.max_chip_size = road.positive("max_chip_size");
  if (road.contains("min_chip_size")) spec.min_chip_size = road.positive("min_chip_size");
  spec.grading_exponent = road.positive("grading_exponent", spec.grading_exponent);
  spec.shape_factor = road.positive("shape_factor", spec.shape_factor);
  spec.elongation = road.positive("elongation", spec.elongation);
  spec.coverage = road.positive("coverage", spec.coverage);
  spec.binder_level = road.non_negative("binder_level", spec.binder_level);
  spec.texture = road.choice("texture", {"positive", "negative"}, "positive") == "negative"
                     ? AggregateRoadSpec::Texture::negative
                     : AggregateRoadSpec::Texture::positive;
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

std::unique_ptr<SampledSurface> make_aggregate_surface(const AggregateRoadSpec& spec) {
  if (!std::isfinite(spec.x_max)) throw std::invalid_argument("make_aggregate_surface: x_max must be finite");
  if (!(spec.half_width >= 0.0) || !std::isfinite(spec.half_width)) {
    throw std::invalid_argument("make_aggregate_surface: half_width must be finite and >= 0");
  }
  const Checked k = check(spec);
  require_in("width", spec.width, 0.0, true, std::numeric_limits<double>::max(), false, "(0, inf) m");
  if (spec.half_width > spec.width / 2.0) {
    throw_bad("width", "the surface is " + format_number(spec.width) +
                           " m wide (y from -width/2 to width/2), but the tyre's contact grid reaches |y| = " +
                           format_number(spec.half_width) + " m; set width to at least " +
                           format_number(2.0 * spec.half_width) + " m");
  }
  const std::size_t last = points_to(std::max(spec.length, spec.x_max), k.spacing, "sample_spacing");
  const std::size_t half_y = points_to(spec.width / 2.0, k.spacing, "sample_spacing");
  const double points = static_cast<double>(last + 1) * static_cast<double>(2 * half_y + 1);
  if (points > static_cast<double>(max_synthesis_points)) {
    throw_bad("sample_spacing", "the surface needs " + format_number(points) +
                                    " samples, more than the limit of 2^26; use a larger sample_spacing, a "
                                    "shorter length or a smaller width");
  }
  std::vector<double> z = build_heights(spec, k, last + 1, half_y);
  return std::make_unique<SampledSurface>("aggregate", k.spacing, last + 1, 2 * half_y + 1, std::move(z));
}

}  // namespace rollnoise
