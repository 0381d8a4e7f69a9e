#pragma once
// Texture spectrum of a profile in third-octave bands of wavelength, ISO 13473-4:2008:
// texture levels L_tx = 10 lg(a_rms² / a_ref²) dB re a_ref = 1 µm (MODEL.md §1).
//
// Estimator (§6, DFT with band summation): the least-squares line is removed from the whole
// profile, a Hann window is applied, and the one-sided squared DFT magnitudes are summed over
// the bins whose spatial frequency k/L lies in the band [f_c·10^(-1/20), f_c·10^(1/20)).
// The sum is divided by N²·mean(w²) (the window's power loss), so that by Parseval's theorem
// the bands add up to the mean square of the windowed profile: exact in expectation for a
// broadband profile, and exact for a sine whose main lobe (±2 bins) lies inside its band.
#include <span>
#include <vector>

namespace rollnoise {

struct TextureBand {
  double nominal_wavelength_m;  // nominal centre (0.5, 0.63, 0.8, 1, ... mm)
  double centre_wavelength_m;   // exact centre, 1 mm · 10^(k/10)
  double level_db;              // L_tx, dB re 1 µm
};

// A band is resolved by a profile of length L (m) at spacing Δ when its short-wavelength edge is
// at least 2Δ (no band above the Nyquist frequency) and its long-wavelength edge is at most
// L / texture_band_length_factor: then the band holds at least 0.2316·12/1.122 ≈ 2.5 DFT bins,
// and the Hann window's leakage (its main lobe is 4 bins wide) stays a fraction of the band.
inline constexpr double texture_band_length_factor = 12.0;

// ISO 13473-4 third-octave band set: nominal centre wavelengths (m) from `shortest_m` to
// `longest_m` (defaults 0.5 mm … 500 mm; nominal values 0.5, 0.63, 0.8, 1, 1.25, 1.6, 2, 2.5,
// 3.15, 4, 5, 6.3, 8, 10 … mm), shortest first. A bound that is a band's exact or nominal centre
// includes that band. Bounds not finite, <= 0 or out of order are an InputError (key "wavelength").
std::vector<double> texture_band_nominal_wavelengths(double shortest_m = 0.5e-3, double longest_m = 0.5);

// Exact (base-10) centre wavelength of the band with this nominal value: 1 mm · 10^(k/10) with
// k the nearest integer to 10 lg(nominal / 1 mm). Not finite or <= 0: InputError ("wavelength").
double texture_band_centre_wavelength(double nominal_m);

// L_tx per third-octave band, dB re 1 µm, for every band of the default set (0.5 … 500 mm)
// that the profile resolves (see texture_band_length_factor), shortest wavelength first.
// z: clean heights (m) at `spacing_m`. A spacing not finite and > 0 is an InputError (key
// "spacing"); a non-finite height or fewer than 4 samples is an InputError (key "profile").
// A band with no energy at all has level -inf.
std::vector<TextureBand> texture_spectrum(std::span<const double> z, double spacing_m);

}  // namespace rollnoise
