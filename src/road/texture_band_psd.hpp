#pragma once
// The spectral density of road texture given as third-octave texture levels (ISO 13473-4):
// the target of the texture generator (texture_road.hpp), along a line (1-D) and over the
// plane for an isotropic surface (2-D).
//
// Levels. L_tx = 10 lg(a_rms^2 / a_ref^2), a_ref = 1 µm, a_rms the rms height of the profile
// filtered to the band: the band holds a variance P = a_ref^2 10^(L_tx / 10) (m^2).
// Bands. Base-10 third octaves in wavelength: edges at centre * 10^(-1/20) and
// centre * 10^(+1/20), i.e. in wavenumber n = 1/lambda (cycles/m) from 10^(-1/20) / centre to
// 10^(1/20) / centre.
//
// Interpolation between band centres. The one-sided 1-D density G(n) (m^2 per cycle/m) is
// constant within each band, from edge to edge: G = P / (n_high - n_low); zero outside the given
// bands (and in the gaps between bands that are not adjacent). So each band holds exactly its
// variance P, and the band level of an ideal analysis equals the target.
//
// Isotropic 2-D density. A line in any direction through an isotropic surface with two-sided
// 2-D density S(q), q = |(nx, ny)|, has the two-sided 1-D density
//     S1(n) = G(|n|)/2 = ∫ S(sqrt(n^2 + ny^2)) dny          (the Abel transform of S),
// whose inverse is
//     S(q) = -(1/pi) ∫_q^∞ S1'(n) / sqrt(n^2 - q^2) dn.
// For the piecewise constant G, S1' is a sum of steps dG_e/2 at the band edges e, so
//     S(q) = -(1/(2 pi)) Σ_{e > q} dG_e / sqrt(e^2 - q^2),   dG_e = G(e+) - G(e-),
// with an integrable inverse-square-root peak just below each edge. A grid samples S as its mean
// over a radial interval of the grid's wavenumber step, which is exact in closed form:
// ∫ dq / sqrt(e^2 - q^2) = asin(q / e).
// Realisability: S must be >= 0. It is where G does not increase with n (a texture spectrum
// whose levels fall by no more than 1 dB per band towards longer wavelengths, as levels in
// constant-percentage bands do on a density that falls with n); elsewhere S is set to 0, which
// changes the line spectrum only at wavenumbers below the offending edge (longer wavelengths).
// The step from 0 up to G at the lowest edge of the longest band always gives S < 0 below it:
// set to 0, it leaves a line through the surface some variance at wavelengths longer than the
// longest band (the projection of the annulus onto the disc); the given bands are unaffected.
#include <cstddef>
#include <span>
#include <vector>

namespace rollnoise {

class TextureBandPsd {
 public:
  // `centres_m`: exact band centre wavelengths (m), increasing, at least a third octave apart;
  // `levels_db`: L_tx (dB re 1 µm), finite. Checked by the caller (std::invalid_argument).
  TextureBandPsd(std::span<const double> centres_m, std::span<const double> levels_db);

  // One-sided 1-D density G(n) (m^2 per cycle/m) at wavenumber |n| (cycles/m).
  double line_density(double n) const;
  // Two-sided isotropic 2-D density S (m^2 per (cycle/m)^2), mean over q in [q_low, q_high]
  // (cycles/m, 0 <= q_low < q_high), clipped at 0.
  double isotropic_density(double q_low, double q_high) const;

  // The integral of the unclipped S along a line of constant nx: ∫_0^ny S(sqrt(nx^2 + t^2)) dt
  // (m^2 per cycle/m; odd in ny). With b_e = sqrt(e^2 - nx^2) for each edge e > |nx|, it is in
  // closed form -(1/(2 pi)) Σ_e dG_e asin(min(|ny|, b_e) / b_e) sign(ny); over all ny it gives
  // G(|nx|)/2 (the Abel transform). A synthesis grid cell [ny1, ny2] at nx holds the difference of
  // two of these, clipped at 0: the cells along nx then sum to the line density exactly,
  // however coarse the grid is in ny; texture_waves.hpp draws lateral wavenumbers from them.
  double isotropic_line_cumulative(double nx, double ny) const;
  // The cells of that integral along the line of constant nx >= 0: `bound` gets 0 and the
  // lateral wavenumbers sqrt(e^2 - nx^2) where the line crosses each edge e > nx, `cumulative`
  // isotropic_line_cumulative at each bound, `weight` each cell's integral clipped at 0 (S keeps
  // its sign within a cell). Returns the sum of the weights, the integral over k >= 0: a quarter
  // of the one-sided line density that an isotropic surface with S clipped at 0 has at nx (the
  // target G(nx)/4 where S is realisable).
  double isotropic_line_cells(double nx, std::vector<double>& bound, std::vector<double>& cumulative,
                              std::vector<double>& weight) const;
  // The one-sided line density (m^2 per cycle/m) of the isotropic surface with S clipped at 0,
  // along any line: 4 × isotropic_line_cells. G(n) where S is realisable; it differs below the
  // lowest band (and below an edge where the levels rise by more than 1 dB per band towards
  // longer wavelengths), where the clipped surface's lines hold variance the bands do not.
  double realisable_line_density(double n) const;
  // The band edges where G changes (cycles/m), increasing.
  const std::vector<double>& edges() const noexcept { return edge_n_; }
  // The largest wavenumber where S is not 0: the highest band edge (cycles/m).
  double highest_wavenumber() const noexcept { return edge_n_.back(); }

  // Total variance of the given bands (m^2).
  double variance() const noexcept { return variance_; }
  // The shortest and longest wavelengths of the spectrum: the outer band edges (m).
  double shortest_wavelength() const noexcept { return 1.0 / edge_n_.back(); }
  double longest_wavelength() const noexcept { return 1.0 / edge_n_.front(); }

 private:
  // Sorted by increasing wavenumber: the band edges where G changes, and G just above each.
  std::vector<double> edge_n_;
  std::vector<double> density_above_;  // G on (edge_n_[k], edge_n_[k+1]); 0 above the last
  std::vector<double> step_;           // dG at edge_n_[k]
  double highest_rising_edge_ = 0.0;   // the largest edge with dG > 0
  double variance_ = 0.0;
};

}  // namespace rollnoise
