#pragma once
// The Gaussian spectrum whose translation has a measured spectrum (profile_surface_road.hpp).
//
// A translation field h = Q(Phi(g / sigma_g)) (Grigoriu, J. Eng. Mech. 110 (1984) 610-620) maps
// a stationary Gaussian field g, point by point, to any height distribution Q; but the map also
// moves power between wavenumbers, so g must be given a spectrum other than the target for h to
// have it. That spectrum is found by iteration, as Shields, Deodatis & Bocchini (Probab. Eng.
// Mech. 26 (2011) 511-519) do for translation processes and as IAAFT (Schreiber & Schmitz,
// Phys. Rev. Lett. 77 (1996) 635) does for one record: make g with the current band levels,
// translate it, analyse h in the same third-octave bands, and correct each band's Gaussian level
// by the miss in dB: G_b <- G_b + (T_b - H_b). The map keeps the record's variance but moves a
// little of it outside the bands (harmonics): the heights are scaled by s, the square root of
// the bands' variance over what the map left in them, so that the bands hold the record's
// (skewness and kurtosis are unchanged by a scale; the MPD scales with it). The shape of the
// distribution is exact by construction; the
// spectrum converges to within 0.05 dB in three iterations for the CAPTIF fine asphalt (skewness
// -0.6, kurtosis 4.7 within its bands) and to about 0.3 dB in ten for the CAPTIF chip seal.
//
// The iteration runs on one long line of the road as it will be made (`make_line`: one period of
// a line of the translated road with the given Gaussian band levels, a fixed seed): the Gaussian
// levels are a property of the record and of how the road is made, not of the realisation a
// user asks for. An isotropic surface's lines carry, beside the bands, the variance that its
// realisable 2-D spectrum adds at longer wavelengths (texture_band_psd.hpp), and the map
// spreads it too: calibrating on such a line takes that into account.
#include <functional>
#include <span>
#include <vector>

namespace rollnoise {

struct TranslationSpectrum {
  std::vector<double> gaussian_levels_db;  // L_tx of g per band
  double scale = 1.0;                      // the heights' factor: s Q(Phi(u)) has the levels T_b
  double worst_miss_db = 0.0;              // max |T_b - H_b| at the last iteration
  int iterations = 0;
};

// One period of a line of the translated road (m) with these Gaussian band levels, before the
// scale s.
using TranslatedLineMaker = std::function<std::vector<double>(const std::vector<double>& gaussian_levels_db)>;

// `centres_m`: exact band centres, increasing; `target_db`: their levels; `spacing_m`: the line's
// sample spacing. The line must resolve every band (at least 12 longest band wavelengths long).
TranslationSpectrum calibrate_translation(std::span<const double> centres_m, std::span<const double> target_db,
                                          double spacing_m, const TranslatedLineMaker& make_line);

// The length of line (m) calibrate_translation should be given: 400 longest band wavelengths,
// at least 4096 and at most 2^20 samples.
double translation_calibration_length(std::span<const double> centres_m, double spacing_m);

}  // namespace rollnoise
