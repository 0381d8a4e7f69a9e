#pragma once
// A road synthesised from its texture spectrum: third-octave texture levels L_tx over texture
// wavelength bands (ISO 13473-4), as a 1-D profile (make_texture_profile) or a 2-D height map
// for the lateral lines of a tyre's contact patch (make_texture_surface). [road] type = "texture".
//
// Keys. `wavelengths` (m): band centres, increasing, each a base-10 third-octave centre of the
// ISO 13473-4 set from 0.5 mm to 500 mm (nominal 0.5, 0.63, 0.8, 1, 1.25 … 500 mm, or the exact
// centres 10^(k/10) mm; nominal values are taken as the exact centre they name); `levels`
// (dB re 1 µm): L_tx of each band, one per wavelength; `seed` (default 1); `length` (m, default
// 100 for a profile, 20 for a surface); `width` (m, surfaces only, default 0.5); `sample_spacing`
// (m, default a quarter of the shortest band's lower edge wavelength; at most half of it, the
// Nyquist limit of that band); `lead_in` (m, default the longest band's upper edge wavelength);
// `anisotropy` (surfaces only) = "isotropic" (default) | "transverse" | "longitudinal".
//
// Spectrum: constant density within each band edge to edge, and the isotropic 2-D density from
// the Abel inversion of the line density (texture_band_psd.hpp). Random phases: spectral
// synthesis with complex normal amplitudes (spectral_synthesis.hpp), absolute, not rescaled, so
// the band levels are the target in expectation (a single profile scatters about it as a
// chi-square with 2 × (modes in the band) degrees of freedom).
//
// Anisotropy of a surface, precisely:
//  - "isotropic": the 2-D density depends on |(nx, ny)| only; a line in any direction has the
//    target spectrum.
//  - "transverse" (transverse tining, grooves across the road): r(x, y) = p(x), one profile with
//    the target spectrum on every longitudinal line; lines across the road are constant.
//  - "longitudinal" (longitudinal tining, grooves along the road): r(x, y) = p(y) w(x), w the
//    lead-in window; every line across the road has the target spectrum; lines along the road
//    are constant beyond the lead-in.
//
// Extent, as for the random roads: the profile covers [0, max(length, x_max)], the surface also
// |y| <= width/2; a run within them sees the same road whatever its duration. Periodic synthesis
// grids keep a margin of two longest wavelengths (and at least eight of them) beyond the extent,
// so the ends are not correlated through the wrap. A raised-cosine window over the first lead_in
// metres takes r to 0 at x = 0 with zero slope (r = 0 for x < 0, the flat lead-in).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "road/sampled_road.hpp"

namespace rollnoise {

class ConfigTable;

struct TextureRoadSpec {
  enum class Anisotropy { isotropic, transverse, longitudinal };

  std::vector<double> wavelengths;  // m, band centres (nominal or exact)
  std::vector<double> levels;       // dB re 1 µm
  std::optional<double> sample_spacing;  // m
  std::optional<double> lead_in;         // m
  std::uint64_t seed = 1;
  double length = 100.0;  // m
  double width = 0.5;     // m (surface)
  Anisotropy anisotropy = Anisotropy::isotropic;  // (surface)
  double x_max = 0.0;       // the run's largest x (m)
  double half_width = 0.0;  // the run's largest |y| (m), <= width / 2 (surface)
};

// Reads the keys of a [road] table of type "texture" into `spec`; `surface` says whether the
// 2-D keys (width, anisotropy) are allowed, `default_length` is the default of `length`.
void read_texture_keys(const ConfigTable& road, TextureRoadSpec& spec, bool surface, double default_length);

// The exact band centres (m) of spec.wavelengths, after checking the bands and levels. Bad input
// is an InputError whose key is the bare key name and whose source is empty.
std::vector<double> checked_texture_band_centres(const TextureRoadSpec& spec);

// Both generate the road; bad parameters are InputErrors naming the bare key (the factories add
// the file and the section).
std::unique_ptr<SampledProfile> make_texture_profile(const TextureRoadSpec& spec);
std::unique_ptr<SampledSurface> make_texture_surface(const TextureRoadSpec& spec);

}  // namespace rollnoise
