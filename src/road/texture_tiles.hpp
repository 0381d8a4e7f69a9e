#pragma once
// The isotropic texture surface (texture_road.hpp) made in tiles along the road, so that its
// memory and time grow with the strip a tyre reads and not with the run's length (issue 26).
//
// Why tiles, and why this lateral period. The surface was one periodic synthesis grid over the
// whole road, at least eight longest wavelengths in each direction: a 1 m, 0.25 mm road with
// bands to 200 mm needed 213 million points (7 m long x 1.8 m across for a 0.5 m wide road), a
// 20 m, 1 mm road with bands to 500 mm 95 million. Here:
//  - Across the road the period is the surface's width plus two longest wavelengths (a margin
//    that keeps lines near one edge from being correlated, through the wrap, with lines near the
//    other at the longest wavelengths), not eight longest wavelengths: each cell of the
//    wavenumber grid holds the 2-D density integrated exactly across its ny interval
//    (TextureBandPsd::isotropic_line_cumulative), so the cells of one nx sum to the line density
//    G(nx)/2 whatever the lateral period, and every line along x has the target spectrum.
//  - Along the road, tile k is an independent periodic field of core + overlap samples (seed
//    mixed from the road's seed and k); the road takes tile k's first `overlap` samples blended
//    with tile k-1's last ones, with weights cos(theta), sin(theta) (theta from 0 to pi/2 with
//    zero slope at both ends): the variance is the same everywhere (cos^2 + sin^2 = 1), the road
//    is continuous with a continuous slope, and only within the overlaps (2 longest wavelengths of
//    every core of at least 16) is the correlation at lag tau lowered, by the factor
//    cos(theta(x) - theta(x + tau)).
//  - Each tile synthesises only the lines it is asked for (a pruned 2-D inverse FFT: the lateral
//    transform of each nx column, keeping the strip's lines, then one transform along x per
//    line), so a strip of a few lines costs a few lines of memory.
// Amplitudes are fixed with random phases (SynthesisAmplitudes::fixed): the mean over all lines of
// a tile's lateral period holds the target spectrum exactly; a single line of an isotropic
// surface is a sum of many lateral modes per nx, so its band levels scatter as a Gaussian
// field's (about ±4.3/sqrt(M) dB for M spectral lines in the band).
#include <array>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "road/road_surface.hpp"
#include "road/texture_band_psd.hpp"

namespace rollnoise {

struct TextureTileLayout {
  double spacing = 0.0;     // m
  std::size_t core = 0;     // samples of road per tile
  std::size_t overlap = 0;  // samples blended with the tile before
  std::size_t n_x = 0;      // core + overlap: the tile's period along x (samples)
  std::size_t n_y = 0;      // the lateral period (samples)
};

// The layout for a surface `width` wide at `spacing` whose longest band edge is
// `longest_wavelength`: overlap = 2 longest wavelengths, core >= 16 longest wavelengths and
// >= 0.5 m, n_y >= width + 2 longest wavelengths (FFT-friendly sizes). A tile of more than
// max_synthesis_points (lateral period x tile length) is an InputError naming sample_spacing.
TextureTileLayout texture_tile_layout(double spacing, double longest_wavelength, double width);

// Tile `index` of the field: lines y = j·spacing, j = -half_lines .. half_lines, each n_x
// samples along x (local x = i·spacing); row-major [i·(2·half_lines + 1) + (j + half_lines)].
std::vector<double> synthesise_texture_tile(const TextureBandPsd& psd, const TextureTileLayout& layout,
                                            std::uint64_t seed, std::size_t index, std::size_t half_lines);

// r(x, y) for x >= 0 and |y| <= half_lines·spacing: the blended tiles times the lead-in window;
// r = 0 for x < 0. Tiles are made as the road is read (two held), under a lock.
class TiledTextureSurface final : public RoadSurface {
 public:
  TiledTextureSurface(TextureBandPsd psd, TextureTileLayout layout, std::uint64_t seed, std::size_t half_lines,
                      double lead_in);

  std::string type() const override { return "texture"; }
  // Bilinear between the samples; |y| beyond the strip is a std::logic_error.
  double height(double x, double y) const override;
  // The road's sample at x = i·spacing, y = j·spacing (|j| <= half_lines).
  double sample(std::size_t i, long j) const;
  const TextureTileLayout& layout() const noexcept { return layout_; }

 private:
  struct Tile {
    std::size_t index = static_cast<std::size_t>(-1);
    std::vector<double> values;
  };
  const std::vector<double>& field(std::size_t index) const;  // raw tile, under mutex_
  const std::vector<double>& road(std::size_t index) const;   // blended and windowed, under mutex_

  TextureBandPsd psd_;
  TextureTileLayout layout_;
  std::uint64_t seed_;
  std::size_t half_lines_;
  double lead_in_;
  // A cache behind the const interface of RoadSurface::height.
  mutable std::mutex mutex_;
  mutable std::array<Tile, 2> fields_;
  mutable std::array<Tile, 2> roads_;
};

}  // namespace rollnoise
