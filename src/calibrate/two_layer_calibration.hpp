#pragma once
// The two-layer tyre (greens/two_layer_tyre.hpp, MODEL.md §4) for calibration: the normal
// receptance between two transducer cells on the tread surface as a function of the belt's,
// the tread's and the inner face's parameters (issue 11).
//
// What is measured. On an elastic surface the point-to-point receptance diverges like 1/r
// (Boussinesq), so force and response are taken over a 10 mm × 10 mm cell each, the footprint
// of an impact hammer's tip and of an accelerometer's base: a uniform load over the source
// cell, the mean displacement over the receiver cell. The point mobility of such a cell is
// largely the tread's local compliance, which lives in modes of wavelengths down to the cell's
// size: summing them mode by mode needs thousands of exact layer solutions per frequency.
//
// How it is computed, per frequency ω:
//   α = Σ_{kept} W_mn Ĝ_zz(k_m, k_n, ω) + Σ_{tail} W_mn Ĝ_zz(k_m, k_n, ω),
//   W_mn = w_m cos(k_m Δx) c_m² · φ_n(y_r) φ_n(y_s) c_n² / (L N_n)   (two_layer_tyre.hpp),
// - kept: every mode whose resonance (estimated as the belt laminate's, bending and transverse
//   shear in series, with tension, foundation and the tread's mass) lies below twice the top of
//   the band to fit, each an exact layer solution. The model file's circumferential_modes and
//   lateral_modes belong to the rolling grid and are not used (nor changed);
// - tail: the modes beyond, whose resonances lie above the band, so that k·Ĝ_zz(k, θ, ω) is
//   smooth there: it is interpolated by a Chebyshev–Lobatto polynomial in ln ρ (12 nodes) times
//   one in cos 2θ (5 nodes; Ĝ is even in k_x and k_y), ρ = k/k_edge(θ) with k_edge where the
//   estimated resonance along θ reaches twice the top (so that the interpolated region holds no
//   resonance in any direction: across, where the tension is low, the kept modes reach
//   k ≈ 140 rad/m, around only 85). The sum over the tail's lattice (orders up to 16·L/(2ℓ)
//   around and 16·b/ℓ across for the cell size ℓ, where the cells' sinc² factors have fallen
//   below 1/(8π)²) reduces to fixed weights on those 60 nodes, computed once per FRF. Kept
//   modes and tail are within 3e-4 of the tyre's own mode-by-mode sum up to the top
//   (tests/calibrate, 28 700 modes).
//
// Derivatives: central differences in each parameter at every node (relative step 1e-5),
// recomputing only the layer the parameter belongs to (a belt modulus leaves the tread's layer
// stiffness as it was; tension and foundation change neither layer). The node values of a
// parameter set and frequency are cached and shared by every FRF's receptance, since a fit's
// FRFs share their frequency lines.
//
// Fittable: the belt's moduli, density and loss factor, the tread's modulus, density and loss
// factor, tension_x, tension_y, foundation_stiffness and foundation_loss_factor. Geometry
// (radius, width, thicknesses) and Poisson's ratios stay as in the file.
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "calibrate/calibration_model.hpp"
#include "greens/two_layer_tyre.hpp"

namespace rollnoise {

class TwoLayerCalibration : public CalibrationModel {
 public:
  // The side of the square cells over which force and response are taken, m.
  static constexpr double transducer_size = 0.010;
  // The top of the band when none is given: the belt modes kept for it (about 150 for the
  // passenger tyre) cost a few ms per frequency; a higher top costs about (top/500 Hz)² more.
  static constexpr double default_band_top_hz = 500.0;
  // A higher top is cut to this: about 1500 kept modes, some 0.2 s per line and iteration.
  static constexpr double largest_band_top_hz = 2000.0;

  // The tail's lattice reaches the orders tail_factor·L/(2ℓ) around and tail_factor·b/ℓ across.
  static constexpr double default_tail_factor = 16.0;

  // `band_top_hz`: the highest frequency to fit (+infinity: default_band_top_hz; at most
  // largest_band_top_hz, where highest_frequency_hz() then cuts the band). Throws
  // std::invalid_argument for a non-physical tyre (the factory reports it as an InputError).
  explicit TwoLayerCalibration(const TwoLayerParameters& parameters,
                               double band_top_hz = std::numeric_limits<double>::infinity(),
                               double tail_factor = default_tail_factor);

  std::string name() const override { return "two_layer"; }
  const std::vector<FitParameter>& parameters() const override { return parameters_; }
  // The belt's in-plane moduli, the tensions, the foundation, the tread's modulus and the three
  // loss factors: what no catalogue gives and a mobility measurement sees (those with a file
  // value of 0, such as an absent foundation_loss_factor, are left out).
  std::vector<std::string> default_free_parameters() const override;
  bool needs_positions() const override { return true; }
  // Positions (x, y) of the cells' centres: y within [ℓ/2, width − ℓ/2].
  std::unique_ptr<ReceptanceFunction> receptance(const FrfPoints& points) const override;
  // The band top the kept modes were chosen for.
  double highest_frequency_hz() const override { return band_top_hz_; }
  // Twice the lowest mode's estimated resonance: the many lightly damped modes above make the
  // cost a plateau from a start some 20 % off (calibration.hpp, frequency continuation), while
  // up to there it falls towards the truth.
  double first_stage_hz() const override { return 2.0 * lowest_resonance_hz_; }
  // The cost rounds at about 1e-11 of itself (the central differences' Jacobian is good to a
  // few 1e-6): 1e-12 would leave the fit some ten iterations of steps in that noise.
  double function_tolerance() const override { return 1e-9; }
  // One: a start is some 20 s (300 lines), and the seeded draws within a factor of ten of the
  // file's values fall far outside the basin that frequency continuation reaches (about 25 %).
  int default_starts() const override { return 1; }

  // The tyre with `values` (one per parameters()) in place of the file's.
  TwoLayerParameters with_values(std::span<const double> values) const;
  // Exact layer solutions per frequency and parameter set: kept modes, and tail nodes.
  std::size_t kept_modes() const;
  std::size_t tail_nodes() const;
  // The last orders of the lattice summed (m = 0 … M around, n up to N across).
  int last_circumferential_order() const;
  int last_lateral_order() const;

  struct Nodes;
  struct Cache;

 private:
  TwoLayerParameters tyre_;
  double band_top_hz_ = 0.0;
  double lowest_resonance_hz_ = 0.0;  // estimated, of the mode (0, first lateral order)
  std::vector<FitParameter> parameters_;
  std::shared_ptr<const Nodes> nodes_;
  std::shared_ptr<Cache> cache_;  // node values per parameter set and frequency, shared by the receptances
};

}  // namespace rollnoise
