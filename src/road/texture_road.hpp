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
// the Abel inversion of the line density (texture_band_psd.hpp). Random phases with fixed
// amplitudes (spectral_synthesis.hpp, SynthesisAmplitudes::fixed; Shinozuka & Deodatis 1991):
// every realisation holds the target, not only the mean over seeds. A profile is one period of
// its own length (at least 8 longest wavelengths), so the periodogram of the whole profile is the
// target in every band, for every seed (issue 26: with complex normal amplitudes a single 20 m
// profile missed bands of 30 to 60 spectral lines by up to ±2.5 dB, a chi-square with 2M degrees
// of freedom). A window (the Hann window of texture_spectrum) mixes neighbouring lines and still
// scatters a band of M lines by about 0.97/sqrt(M) (relative); a shorter piece of the profile
// scatters as any random profile of that length. An isotropic surface is one oblique plane wave
// per wavenumber along x, its lateral wavenumber drawn from the isotropic spectrum
// (texture_waves.hpp): every line along x holds the target exactly, as the profile does.
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
// Extent: the profile covers [0, max(length, x_max)] and is periodic over it (x = 0 and the end
// are neighbours through the wrap: nothing reads both); a run within it sees the same road
// whatever its duration. The isotropic surface has the same period along x and is made line by
// line as it is read (make_rolling_texture_surface; texture_waves.hpp), the same road whatever
// the tyre's width: its memory is that of the lines a tyre reads. `width` bounds |y| <= width/2
// (the whole map, and the check against the tyre's contact grid). The anisotropic surfaces hold
// one line (along x over the road, or across over the width). A raised-cosine window over the first lead_in metres takes r to 0 at x = 0
// with zero slope (r = 0 for x < 0, the flat lead-in).
#include <cstdint>
#include <functional>
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
  // Maps a standard normal height (the Gaussian road over its rms, per period) to the road's
  // height, before the lead-in window; empty: the Gaussian road itself. A surface generated from
  // a measured record gets the record's height distribution through it (profile_surface_road.hpp).
  std::function<double(double)> marginal;
};

// Reads the keys of a [road] table of type "texture" into `spec`; `surface` says whether the
// 2-D keys (width, anisotropy) are allowed, `default_length` is the default of `length`.
void read_texture_keys(const ConfigTable& road, TextureRoadSpec& spec, bool surface, double default_length);

// The exact band centres (m) of spec.wavelengths, after checking the bands and levels. Bad input
// is an InputError whose key is the bare key name and whose source is empty.
std::vector<double> checked_texture_band_centres(const TextureRoadSpec& spec);

// All generate the road; bad parameters are InputErrors naming the bare key (the factories add
// the file and the section). make_texture_surface holds the whole map of [0, max(length, x_max)]
// x |y| <= width/2 (at most 2^26 points), sample for sample the road that
// make_rolling_texture_surface makes line by line for a tyre, which the road factory uses.
std::unique_ptr<SampledProfile> make_texture_profile(const TextureRoadSpec& spec);
// The road's sample spacing (m): sample_spacing, or its default, after the same checks.
double texture_sample_spacing(const TextureRoadSpec& spec);
std::unique_ptr<SampledSurface> make_texture_surface(const TextureRoadSpec& spec);
std::unique_ptr<RoadSurface> make_rolling_texture_surface(const TextureRoadSpec& spec);

// Maps one period of a zero-mean Gaussian line through `marginal` (TextureRoadSpec::marginal):
// each sample over the period's rms.
void map_period_through_marginal(std::vector<double>& period, const std::function<double(double)>& marginal);

}  // namespace rollnoise
