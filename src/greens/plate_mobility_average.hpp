#pragma once
// Spatial averages of the Kropp plate's transfer mobility (kropp_plate.hpp) for a point force:
// how much mean-square velocity a force of unit mean square puts on the belt, over the whole belt
// or over a stretch of it around the force. With the force at (0, y0):
//   Y(x, y; ω) = iω Σ_mn sin(k_n y) sin(k_n y0) e^{i k_m x} H_mn(ω) / M,
//   H_mn = 1/(ω_mn² − ω² + iω η ω_mn),  M = m''·L·b/2 (kropp_plate.hpp),
// and by the orthogonality of the modes over the belt (∫∫ |φ_mn|² = L·b/2, cross terms 0)
//   ⟨|Y|²⟩_belt = (ω²/2) Σ_{m=−M..M} Σ_n sin²(k_n y0) |H_mn|² / M².
// Over |x| ≤ d (all y), the lateral orthogonality still holds and the x integral is taken
// numerically, with 2d/`step` midpoints:
//   ⟨|Y|²⟩_|x|≤d = (ω²/2) Σ_n sin²(k_n y0) mean_x |Σ_m H_mn e^{i k_m x}|² / M².
// ⟨v²⟩ = ⟨|Y|²⟩·⟨F²⟩ for a force of mean square ⟨F²⟩ in a band where |Y|² is averaged over it.
//
// The patch receptance: a unit force spread as a uniform pressure over the patch |x| ≤ l/2,
// |y − b/2| ≤ w/2, and the mean displacement over the same patch,
//   α_patch(ω) = Σ_{m=−M..M} Σ_n P_mn² H_mn / M,
//   P_mn = sinc(k_m l/2) · [cos(k_n(b − w)/2) − cos(k_n(b + w)/2)]/(k_n w)
// (the patch mean of each mode shape). It is what a rigid flat patch pressed on the belt feels;
// the point receptance α(0, y0, y0) overstates it wherever the load's spread matters.
#include <vector>

#include "greens/kropp_plate.hpp"

namespace rollnoise {

// ⟨|Y|²⟩ over the whole belt, (m/(N·s))², force at the lateral position y0 ∈ [0, b].
double belt_mean_square_mobility(const KroppPlate& plate, double y0, double omega);

// ⟨|Y|²⟩ over |x| ≤ half_length (0 < half_length ≤ L/2) along the circumference, all y; the x
// mean is taken at midpoints `step` m apart (or the nearest spacing that divides 2d).
double near_mean_square_mobility(const KroppPlate& plate, double y0, double omega, double half_length,
                                 double step = 2.5e-3);

// The same for many ω: the table of cos(k_m x_i), the same for every ω, made once (the energy
// budget evaluates 8 frequencies in each of some 20 bands; remaking the table each time was a
// third of its cost, issue 12). The plate must outlive it. Equal to the function above bit for bit.
class NearMeanSquareMobility {
 public:
  NearMeanSquareMobility(const KroppPlate& plate, double y0, double half_length, double step = 2.5e-3);
  double operator()(double omega) const;

 private:
  const KroppPlate& plate_;
  double y0_;
  int points_ = 1;
  std::vector<double> cosines_;  // 2·cos(k_m x_i) at [(m − 1)·points + i]
};

// α_patch (m/N) for a patch of length l along x and width w ≤ b across, centred on the belt.
std::complex<double> patch_receptance(const KroppPlate& plate, double length, double width, double omega);

}  // namespace rollnoise
