#pragma once
// A road surface built from its aggregate mix: stones of a given grading and shape placed at
// random on a plane and embedded in a binder. [road] type = "aggregate". A 2-D height map
// (make_aggregate_surface) for the lateral lines of a tyre, or a 1-D profile
// (make_aggregate_profile), a line of such a map. The model and its limits:
// docs/road_aggregate_model.md.
//
// Model (simple and physical; no packing mechanics):
//  - Stones. Sizes d (the sieve size, taken as the stone's width) between min_chip_size and
//    max_chip_size from a grading curve: the mass fraction passing a sieve d is
//    (d^e - dmin^e) / (dmax^e - dmin^e), e = grading_exponent (e = 0.5 is Fuller's curve); with
//    mass ∝ d^3 the number density is ∝ d^(e-4). Each stone is an ellipsoid lying flat (its
//    least dimension vertical, as rolling and traffic leave chips; ALD = shape_factor · d),
//    semi-axes a = elongation · d/2 (long, horizontal), b = d/2, c = shape_factor · d/2
//    (vertical), turned by a uniform random angle about the vertical.
//  - Placement: random sequential placement, uniform positions, overlaps allowed; the surface is
//    the highest stone at each point (a Boolean model). Stones are added until their footprint
//    areas sum to -ln(1 - coverage) per unit area, so that `coverage` is the expected fraction of
//    the plane covered by stones.
//  - Binder: a level z_b = binder_level · T, T = shape_factor · max_chip_size the thickness of the
//    largest stone, below which everything is filled (between the stones the surface is z_b).
//  - texture = "positive" (surface dressing, chip seal): every stone rests on the substrate
//    z = 0, so its top is at 2c; the tops stand up from the binder.
//    texture = "negative" (SMA, porous asphalt): the stones are pressed into the mix from a
//    common top plane z = T, as by the roller: each stone's upper cap is cut flat at that plane
//    (its ellipsoid would reach 0.3 c above it), giving a flat top surface with the voids and
//    grooves between stones below it, down to the binder.
//    texture = "rolled" (a dense mix laid by a paver and compacted by steel rollers; keys sieves,
//    passing, binder_content, air_voids instead of max_chip_size, grading_exponent, coverage,
//    binder_level): the stones (sizes min_chip_size ... the first sieve passing 100 %, drawn from
//    the sieve curve, linear in log size between sieves) lie at uniform random depths in the mix,
//    at the coarse aggregate's volume fraction (a Boolean model in 3-D); a stone that would stand
//    above the roller's plane z = 0 is cut flat there. The mastic (binder and the aggregate finer
//    than min_chip_size) fills the pore space between the stones from below: every column of the
//    layer of one largest stone's thickness T under the plane takes the mix's share V_m·T (with
//    one offset per mix for what crowded columns cannot hold), and the columns' levels are
//    averaged over a square of the largest stone, the pocket the mastic levels out in under the
//    roller (road/rolled_mastic.hpp). Above the mastic the space between the stones is open: the
//    air voids.
//  - Heights: the visible upper surface, max(z_b, max over stones of the stone's upper surface),
//    minus its mean over the generated grid (r = 0 is the mean level), times a raised-cosine
//    lead-in window over the first lead_in metres (r = 0 for x < 0, the flat lead-in).
// Limits: no stone-on-stone support or interlock (a stone does not rest on another, they
// interpenetrate and the higher surface is kept), no stone tilt, no surface microtexture below
// the stones' curvature, the binder is flat, a single layer.
//
// Keys: max_chip_size (m, required), min_chip_size (m, default 0.25 · max_chip_size),
// grading_exponent (in (0, 2], default 0.5), shape_factor (c/b, in (0, 1], default 0.7),
// elongation (a/b, in [1, 4], default 1), coverage (in (0, 1), default 0.85), binder_level (in
// [0, 1), default 0.1) — the defaults are the calibration to the CAPTIF chip seal (with
// max_chip_size = 0.0132), see the docs —
// texture = "positive" (default) | "negative" | "rolled" (with sieves, passing, binder_content,
// air_voids; min_chip_size then defaults to 2 mm), seed (default 1), length (m, default 100 for a
// profile, 5 for a surface), width (m, surface only, default 0.5), sample_spacing (m, default
// max_chip_size / 20, at most min_chip_size / 4), lead_in (m, default 4 · max_chip_size).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "road/sampled_road.hpp"

namespace rollnoise {

class ConfigTable;

struct AggregateRoadSpec {
  enum class Texture { positive, negative, rolled };

  double max_chip_size = 0.0;                 // m, > 0
  std::optional<double> min_chip_size;        // m, (0, max_chip_size]; default 0.25 max
  double grading_exponent = 0.5;              // e, (0, 2]
  double shape_factor = 0.7;                  // c / b, (0, 1]
  double elongation = 1.0;                    // a / b, [1, 4]
  double coverage = 0.85;                     // (0, 1)
  double binder_level = 0.1;                  // [0, 1)
  Texture texture = Texture::positive;
  std::optional<double> sample_spacing;       // m
  std::optional<double> lead_in;              // m, >= 0
  std::uint64_t seed = 1;
  double length = 100.0;    // m
  double width = 0.5;       // m (surface)
  // texture = rolled (a dense mix laid by a paver and compacted by steel rollers): its mix design.
  // max_chip_size, grading_exponent, coverage and binder_level are not used: the largest stone is
  // the smallest sieve that passes 100 %, the grading is the sieve curve, and the stones' density
  // and the mastic's level follow from the volumes of the mix.
  std::vector<double> sieves;    // m, increasing
  std::vector<double> passing;   // % by mass passing each sieve, not decreasing, 100 at the last
  double binder_content = 0.0;   // % by mass of the mix, (0, 100)
  double air_voids = 0.0;        // % by volume of the mix, (0, 100)
  double x_max = 0.0;       // the run's largest x (m)
  double half_width = 0.0;  // the run's largest |y| (m) (surface)
};

// Reads the keys of a [road] table of type "aggregate"; `surface` allows `width`.
void read_aggregate_keys(const ConfigTable& road, AggregateRoadSpec& spec, bool surface, double default_length);

// Both generate the road; bad parameters are InputErrors naming the bare key.
std::unique_ptr<SampledProfile> make_aggregate_profile(const AggregateRoadSpec& spec);
std::unique_ptr<SampledSurface> make_aggregate_surface(const AggregateRoadSpec& spec);

// The surface a rolling tyre needs up to spec.x_max, in memory that does not grow with x_max
// (issue 13). Up to spec.length it is make_aggregate_surface's road, sample for sample. A longer
// run continues it in tiles of that length, each generated when the tyre first reaches it: tile
// k ≥ 1 holds the stones centred in its own stretch, drawn from a seed of its own (seed, k), so
// the stone density is the same everywhere and the tiles join without a seam (a tile's samples
// take the stones of its neighbours that reach over); its heights are referred to tile 0's mean.
// Tiles after the first hold only the strip the tyre reads, |y| ≤ half_width (and a column beyond
// for the interpolation): a third of the default 0.5 m surface. At most two tiles are held. A run of at most `length` gets the SampledSurface itself.
std::unique_ptr<RoadSurface> make_rolling_aggregate_surface(const AggregateRoadSpec& spec);

}  // namespace rollnoise
