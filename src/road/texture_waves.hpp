#pragma once
// The isotropic texture surface (texture_road.hpp) as one oblique plane wave per wavenumber along
// the road, so that every line along the road holds the target spectrum (issue 26), and the
// surface is computed line by line as it is read.
//
// Construction. Along x the road is periodic over its length P (at least 8 longest wavelengths),
// with wavenumbers n_m = m/P. Wavenumber n_m carries one plane wave
//     a_m cos(2 pi (n_m x + k_m y) + phi_m),
// with a fixed amplitude, a uniform random phase phi_m, and a lateral wavenumber k_m drawn from
// the conditional density of the isotropic 2-D spectrum S at n_m, p(k | n_m) = S(sqrt(n_m^2 + k^2))
// / ∫ S dk (both signs of k equally likely). Then:
//  - every line y = const has, at n_m, the amplitude a_m/2 whatever y is (only its phase
//    changes): its periodogram over the road's length is the target line density G in every band,
//    for every seed and every line (a_m^2 = 2 G(n_m)/P, as the 1-D profile's);
//  - over the draws, the 2-D spectrum is G(n)/2 · p(k | n) = S(n, k): the field is isotropic in
//    distribution, and the correlation between two lines a lateral distance d apart is, band by
//    band, the mean of cos(2 pi k_m d) over the band's waves: the isotropic field's, to within
//    about 1/sqrt(M) for a band of M waves;
//  - the heights are Gaussian in the limit of many waves (a sum of independent phases).
// This is the random-wave model of an isotropic field with its directions stratified by the
// wavenumber along x (cf. the spectral representation, Shinozuka & Deodatis, Appl. Mech. Rev. 44
// (1991) 191-204); it keeps what a tyre rolling along x is excited by — each line's spectrum —
// exact per realisation, where a Gaussian field (or one with fixed amplitudes on a 2-D grid of
// wavenumbers) scatters by ±4.3/sqrt(M) dB on each line. What it does not reproduce per
// realisation: the lateral structure of a band of few waves (the longest bands) is a few crossing
// plane waves, as any realisation of so few degrees of freedom is.
//
// The conditional density comes from the exact line integral of S
// (TextureBandPsd::isotropic_line_cumulative), in cells between the lateral wavenumbers where the
// line crosses a band edge (k = sqrt(e^2 - n^2)): S keeps its sign within each. Cells whose
// integral is negative (where the target is not realisable by an isotropic surface: below the
// lowest band, or where the levels fall by more than 1 dB per band towards longer wavelengths)
// are set to 0; a cell is drawn by its weight and k found within it by bisection of the closed
// form. Where
// cells were clipped the wave's power is that of the clipped density (the line gains the variance
// that texture_band_psd.hpp describes); elsewhere it is G.
//
// Lines are made when first read, at y = j·spacing (a lateral grid, with bilinear interpolation
// between lines, as the maps of the other generators): each line is one inverse FFT of the road's
// length. The memory is that of the lines read (a tyre's contact grid reads two road lines per
// lateral line of its own), bounded by max_synthesis_points held at once (older lines dropped).
#include <complex>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <list>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "road/road_surface.hpp"
#include "road/texture_band_psd.hpp"

namespace rollnoise {

class TextureWaveSurface final : public RoadSurface {
 public:
  // `samples`: the road's period along x in samples of `spacing` (>= 2); `lead_in` (m) as for
  // every texture road. Draws the waves (amplitude, phase, lateral wavenumber) from `seed`.
  // `marginal` (optional) maps each sample's standard normal value (the Gaussian height over the
  // lines' rms, the same on every line) to the road's height before the lead-in window
  // (TextureRoadSpec::marginal): the surface of a measured record (profile_surface_road.hpp).
  TextureWaveSurface(const TextureBandPsd& psd, double spacing, std::size_t samples, std::uint64_t seed,
                     double lead_in, std::function<double(double)> marginal = {});

  std::string type() const override { return "texture"; }
  // Bilinear between the samples at (i·spacing, j·spacing); r = 0 for x < 0; x beyond the
  // period is a std::logic_error (the generator was told the run's range).
  double height(double x, double y) const override;
  std::optional<double> sample_spacing() const override { return spacing_; }
  // The sample at x = i·spacing (i <= samples: the last repeats the first, times the lead-in
  // window), y = j·spacing.
  double sample(std::size_t i, long j) const;

  double spacing() const noexcept { return spacing_; }
  std::size_t samples() const noexcept { return samples_; }
  // The waves: lateral wavenumber (cycles/m) of wave m = 1 .. (samples-1)/2, for tests.
  double lateral_wavenumber(std::size_t m) const { return lateral_.at(m); }

 private:
  const std::vector<double>& line(long j) const;  // under mutex_

  double spacing_;
  std::size_t samples_;
  double lead_in_;
  std::vector<std::complex<double>> coefficient_;  // C_m, m = 0 .. samples/2 (FFTW's half spectrum)
  std::vector<double> lateral_;                    // k_m (cycles/m)
  std::function<double(double)> marginal_;
  double rms_ = 0.0;  // of every line before the marginal: sqrt(2 sum |C_m|^2)
  // Lines made so far, by j, and their order of making (the oldest is dropped first).
  mutable std::mutex mutex_;
  mutable std::map<long, std::vector<double>> lines_;
  mutable std::list<long> order_;
};

}  // namespace rollnoise
