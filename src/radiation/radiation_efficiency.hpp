#pragma once
// Radiation efficiency (radiation factor) of a vibrating surface:
//   σ = W / (ρ c S ⟨v²⟩),
// W the radiated sound power (W), S the radiating area (m²), ⟨v²⟩ the mean square normal
// velocity, averaged over S and over time ((m/s)²; per band, with W of the same band). σ = 1 is
// a large plane piston radiating plane waves; a surface whose bending or tension waves are
// slower than sound radiates with σ ≪ 1, mostly from its edges and from where it is driven.
//
// Two closed forms for a surface moving uniformly in phase, the most efficient way for a body to
// radiate (both → 1 at high ka):
//  - a circular piston of radius a in an infinite rigid baffle (Rayleigh; e.g. Kinsler et al.,
//    Fundamentals of Acoustics, §7.5): σ = 1 − J1(2ka)/(ka), ≈ (ka)²/2 at low ka;
//  - an infinitely long pulsating cylinder of radius a (e.g. Junger & Feit, Sound, Structures
//    and Their Interaction, §4): the surface impedance ρc·iH0(ka)/H1(ka) gives
//    σ = 2/(π ka |H1(ka)|²), |H1|² = J1² + Y1², ≈ π ka/2 at low ka.
namespace rollnoise {

// σ from its definition. power_w >= 0, density, sound_speed, area > 0, mean_square_velocity > 0
// (std::invalid_argument otherwise).
double radiation_efficiency(double power_w, double density, double sound_speed, double area,
                            double mean_square_velocity);

double baffled_piston_radiation_efficiency(double ka);
double pulsating_cylinder_radiation_efficiency(double ka);

}  // namespace rollnoise
