#pragma once
// A 2-D road surface made from measured lines: [road] type = "profile_surface". A road engineer's
// laser gives lines; a tyre needs a patch. From one or a few measured lines (any profile file the
// readers accept, profile_file.hpp) this makes an isotropic surface, as long as the run, whose
// every line has the record's texture spectrum and its height distribution.
//
// Method (a translation field with an iterated spectrum; physics page docs/physics/roads.md):
//  1. The record (record_texture.hpp): the third-octave texture levels T_b of the bands it
//     supports (wavelengths from 2 × spacing to a quarter of its shortest line), and its heights
//     restricted to those bands, whose empirical distribution Q (height_distribution.hpp) is kept.
//  2. The levels of the surface's lines: T_b, or for an isotropic surface the levels its lines
//     have when its 2-D spectrum is the Abel inverse of T_b clipped at 0 (texture_band_psd.hpp):
//     T_b where the record's levels fall towards longer wavelengths by no more than about 1 dB
//     per band, more just beyond a steeper fall, which no isotropic surface has (a short
//     record's longest bands, estimated from few modes, often fall so).
//  3. The Gaussian levels G_b whose translation s Q(Phi(g / sigma)) has those levels
//     (translation_calibration.hpp), and the map Q corrected, IAAFT-like, until the translated
//     lines, band-passed in pieces as long as the record's, have the record's skewness and
//     kurtosis (the map's harmonics outside the bands carry some of the distribution's tails).
//  4. A Gaussian isotropic texture surface with the levels G_b, one oblique plane wave per
//     wavenumber along x (texture_waves.hpp), mapped point by point through Q(Phi(g / sigma)),
//     then the lead-in window. Lines across the road are as correlated as isotropy says: the
//     map is the same at every point, so the field stays isotropic.
// What it keeps: each line's spectrum in the supported bands (within a few tenths of a dB), the
// distribution of heights within the bands (skewness and kurtosis). What it cannot keep: the MPD
// where it depends on more than the spectrum and the distribution (a chip seal's flat stone tops:
// +12 %, where IAAFT surrogates of the record give +9 %), the shapes of individual stones (a
// translated Gaussian field has no edges or flat faces, only its heights' distribution and
// correlation), anything at wavelengths the record does not support, and any dependence between
// the phases of different wavelengths beyond what the map makes.
//
// Keys: file (required: a profile file, or a list of them at the same spacing; relative to the
// file that sets it), seed (default 1), length (m, default 20), width (m, default 0.5),
// sample_spacing (m, default a quarter of the shortest band's lower edge), lead_in (m, default
// the longest band's upper edge), anisotropy ("isotropic" default, "transverse",
// "longitudinal", as the texture road's). The extent, memory and lead-in are the texture road's
// (texture_road.hpp).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "road/height_distribution.hpp"
#include "road/record_texture.hpp"
#include "road/road_surface.hpp"

namespace rollnoise {

class ConfigTable;

class ProfileSurfaceRoad final : public RoadSurface {
 public:
  ProfileSurfaceRoad(std::unique_ptr<RoadSurface> surface, RecordTexture record, HeightMoments record_moments,
                     std::vector<double> levels_db, std::vector<double> gaussian_levels_db, double spacing,
                     std::vector<std::string> warnings);

  std::string type() const override { return "profile_surface"; }
  double height(double x, double y) const override { return surface_->height(x, y); }
  std::optional<double> sample_spacing() const override { return spacing_; }
  std::vector<std::string> warnings() const override { return warnings_; }

  // The record the surface was made from: its bands, levels and band-limited heights.
  const RecordTexture& record() const noexcept { return record_; }
  // The moments of the record's band-limited heights, all lines pooled.
  const HeightMoments& record_moments() const noexcept { return record_moments_; }
  // The band levels of the surface's lines, per record band: the record's, or for an isotropic
  // surface the nearest an isotropic surface has (higher just beyond a steep fall of the record's
  // levels towards longer wavelengths: step 2 of the method above).
  const std::vector<double>& levels_db() const noexcept { return levels_db_; }
  // The Gaussian field's band levels (before the map).
  const std::vector<double>& gaussian_levels_db() const noexcept { return gaussian_levels_db_; }

 private:
  std::unique_ptr<RoadSurface> surface_;
  RecordTexture record_;
  HeightMoments record_moments_;
  std::vector<double> levels_db_;
  std::vector<double> gaussian_levels_db_;
  double spacing_;
  std::vector<std::string> warnings_;
};

// Builds the surface of a [road] table of type "profile_surface" for a run over x <= x_max and
// |y| <= half_width. Unknown keys are rejected; bad values are InputErrors naming "[road] key" in
// the file that set it, or the data file.
// RoadBuild::keys_only: the keys only, nullptr (road_profile.hpp).
std::unique_ptr<ProfileSurfaceRoad> make_profile_surface(const ConfigTable& road, double x_max, double half_width,
                                                         RoadBuild build = RoadBuild::road);

}  // namespace rollnoise
