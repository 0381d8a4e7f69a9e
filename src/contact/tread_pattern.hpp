#pragma once
// The tread pattern as macro-roughness of the tyre (Andersson, Larsson & Kropp, ICA 2001:
// "points at the blocks may be in contact with the road while forces at points in the grooves
// are set to zero"): a height map h(s, y) ≤ 0 over the tread, s the material coordinate along the
// circumference (period 2πR), y across from the tread's centre line. The block surface is the
// slick's surface (h = 0); a groove is h = −depth. The contact adds −h to the gap of the cell that
// holds the material point, as it subtracts the road's height (rolling_tyre.cpp), so a point in a
// groove deeper than the local indentation carries no force.
//
// Three kinds of features, the deepest wins where they overlap:
//  - lateral grooves, one at the start of each pitch: pitch k spans [s_k, s_k+1) with
//    s_k = L·Σ_{i<k} ℓ_i / Σ ℓ_i (relative lengths ℓ, equal for `pitches = N`); the groove is
//    `width` wide normal to its direction and inclined by `angle` from the lateral, so it covers
//    |s − s_k − y·tan α| < width/(2 cos α) along the circumference;
//  - circumferential grooves (ribs between them): |y − position| < width/2, all around;
//  - a tabulated map h(x_i, y_j) on N lines spaced L/N around from s = 0 (periodic bilinear
//    interpolation along s, bilinear across).
#include <optional>
#include <span>
#include <vector>

namespace rollnoise {

struct TreadRib {
  double position = 0.0;  // m, centre of the circumferential groove from the tread's centre line
  double width = 0.0;     // m
  double depth = 0.0;     // m, ≥ 0
};

struct TreadHeightMap {
  std::vector<double> y;  // m from the tread's centre line, increasing, ≥ 2 lines
  std::vector<double> z;  // m, ≤ 0; z[i·ny + j] at s_i = i·L/nx, y_j
  std::size_t lines_around = 0;  // nx
};

struct TreadPatternGeometry {
  std::vector<double> pitch_lengths;  // relative (> 0); empty: no lateral grooves
  double groove_width = 0.0;          // m, normal to the groove
  double groove_depth = 0.0;          // m
  double groove_angle = 0.0;          // rad from the lateral (|α| < π/2)
  std::vector<TreadRib> ribs;
  std::optional<TreadHeightMap> map;
};

class TreadPattern {
 public:
  // `circumference`: 2πR of the tread surface (m). Inconsistent geometry (a groove as long as the
  // shortest pitch, negative depths, a map of no lines) is a std::invalid_argument; the case
  // reader (tread_pattern_reader.hpp) names the key first.
  TreadPattern(TreadPatternGeometry geometry, double circumference);

  double circumference() const noexcept { return circumference_; }
  const TreadPatternGeometry& geometry() const noexcept { return geometry_; }
  // h(s, y) ≤ 0 (m); s any real (periodic in L), y from the tread's centre line.
  double height(double s, double y) const;
  // The mean of h over [y − dy/2, y + dy/2] at s (midpoint rule, 16 samples): a groove narrower
  // than a contact cell gives its share of the depth, as the road's cell average does along x.
  double lateral_mean(double s, double y, double dy) const;
  // The start of each pitch, s_k (m), increasing from 0; empty without lateral grooves.
  std::span<const double> pitch_starts() const noexcept { return starts_; }
  // The circumferential order whose tones the pattern makes: the number of pitches, or for a
  // map the order m ≥ 1 with the largest |Σ_i h̄(s_i)·e^{−2πi·m·i/N}| of the width-mean height h̄;
  // 0 for circumferential grooves only (no tones).
  int tone_order() const;

 private:
  double lateral_groove(double s, double y) const;
  double map_height(double s, double y) const;

  TreadPatternGeometry geometry_;
  double circumference_;
  std::vector<double> starts_;
  double groove_half_length_ = 0.0;  // width/(2 cos α), along the circumference
  double groove_slope_ = 0.0;        // tan α
};

}  // namespace rollnoise
