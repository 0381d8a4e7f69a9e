#pragma once
// Spectral synthesis of stationary Gaussian random fields on periodic grids (MODEL.md §7): the
// inverse FFT of complex normal amplitudes, shared by the random roads and surfaces and the
// texture and ISO 8608 generators. The draws come from std::mt19937_64 through portable_normal,
// so a seed gives the same field on every platform.
//
// Amplitudes. The callers give the standard deviation A of the real and of the imaginary part
// of each Fourier coefficient. With FFTW's unnormalised c2r transform, a coefficient and its
// conjugate twin add 2 Re(X e^{i phi}) to every sample, a variance of 4 A^2. For a one-sided
// (1-D) spectral density G(n) (m^2 per cycle/m) on a period P: A = sqrt(G(n) / P) / 2; for a
// two-sided 2-D density S(nx, ny) (m^2 per (cycle/m)^2) on periods Px x Py:
// A = sqrt(S / (2 Px Py)) (spectral_amplitude_1d / _2d below).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numbers>
#include <vector>

namespace rollnoise {

// Raised cosine over the first `lead_in` metres: 0 with zero slope at x = 0, 1 with zero slope
// at lead_in, so that a generated road leaves the flat lead-in (x < 0) without a jump or a kink.
inline double lead_in_window(double x, double lead_in) {
  if (!(x < lead_in)) return 1.0;
  if (x <= 0.0) return 0.0;
  return 0.5 * (1.0 - std::cos(std::numbers::pi * x / lead_in));
}

// How each Fourier coefficient's random value is drawn.
//  - gaussian: a complex normal (real and imaginary parts normal, standard deviation A): a
//    Gaussian field whose spectrum is the target only in expectation; a band of M modes
//    scatters as a chi-square with 2M degrees of freedom (about ±4.3/sqrt(M) dB).
//  - fixed: modulus sqrt(2)·A (the complex normal's rms) and a uniform random phase: the
//    "spectral representation" of Shinozuka & Deodatis (Appl. Mech. Rev. 44 (1991) 191-204,
//    eq. 45 ff.), whose every realisation holds the target spectrum exactly over one period
//    (its periodogram is the target), and whose heights are Gaussian in the limit of many modes.
enum class SynthesisAmplitudes { gaussian, fixed };

// Largest synthesis grid the generators accept, in points (2^26: 0.5 GiB for one work array).
inline constexpr std::size_t max_synthesis_points = std::size_t{1} << 26;

// The FFT-friendly size of a periodic synthesis grid of at least `needed` points along one axis;
// `needed_total` (>= needed) is the point count of the whole grid, checked against
// max_synthesis_points: too many is an InputError naming sample_spacing (bare key, no source).
std::size_t synthesis_grid_size(double needed, double needed_total);

// A one-sided density G (m^2 per cycle/m) on a period P (m) as the per-part amplitude A.
inline double spectral_amplitude_1d(double one_sided_density, double period) {
  return 0.5 * std::sqrt(one_sided_density / period);
}
// A two-sided 2-D density S (m^2 per (cycle/m)^2) on periods Px, Py (m) as A.
inline double spectral_amplitude_2d(double two_sided_density, double period_x, double period_y) {
  return std::sqrt(two_sided_density / (2.0 * period_x * period_y));
}

// n samples of one period of a 1-D field with spacing `spacing` (period n·spacing). Mode m =
// 1 .. (n-1)/2 at wavenumber m / period (cycles/m) gets amplitude(wavenumber) times a complex
// normal; the mean and the Nyquist mode of an even n are 0. Each mode draws its pair of normals
// in order of m, whatever the amplitude, so the draws do not depend on the spectrum.
std::vector<double> synthesise_periodic_profile(std::size_t n, double spacing, std::uint64_t seed,
                                                const std::function<double(double)>& amplitude,
                                                SynthesisAmplitudes kind = SynthesisAmplitudes::gaussian);

// Fills `data`, an FFTW in-place real-to-complex array of n0 rows of 2 (n1/2 + 1) doubles
// (allocated with fftw_alloc_real), with one period of a 2-D field: row i (x = i·spacing_x, any
// spacing) holds n1 samples along y. Entry (i, k) of the half spectrum, wavenumber
// (nx, ny) = (i'/period_x, k/period_y) with i' the signed index of row i, gets
// amplitude(nx, ny) times a complex normal, drawn in row-major order for every entry; the mean
// and the Nyquist row and column are 0 and the column k = 0 is made Hermitian, so that each
// pair of opposite wavenumbers carries one complex normal.
void synthesise_periodic_surface(double* data, std::size_t n0, std::size_t n1, double period_x,
                                 double period_y, std::uint64_t seed,
                                 const std::function<double(double, double)>& amplitude);

}  // namespace rollnoise
