#pragma once
// The Green's function of a point source over a locally reacting impedance plane, exact: the
// pressure at a receiver over the road z = 0 of normalised surface admittance β = ρ₀c₀/Z_s
// (road/road_absorption.hpp), for time dependence e^{+iωt} as the rest of the radiation stage
// (equivalent_sources.hpp: free field e^{−ikR}/(4πR)). The boundary condition is
// ∂p/∂z = ikβ·p on z = 0, so a plane wave at angle θ from the normal reflects with
// R_p(θ) = (cos θ − β)/(cos θ + β).
//
// With R₁ the distance from the source, R₂ from its image, Z = z + z_s and r the horizontal
// distance, writing R_p = 1 − 2kβ/(k_z + kβ) in the Sommerfeld integral and
// 1/(k_z + kβ) = ∫₀^∞ e^{−(k_z + kβ)s} ds (valid for Re β > 0, a passive surface) gives the
// image of the rigid plane plus a line of sources below it, at the complex heights Z − is:
//   G = e^{−ikR₁}/(4πR₁) + e^{−ikR₂}/(4πR₂) − (2kβ/4π) ∫₀^∞ e^{−kβs} e^{−ikR(s)}/R(s) ds,
//   R(s) = √(r² + (Z − is)²)  (principal root)
// (Di & Gilbert, JASA 93 (1993) 714–720; Ochmann, JASA 116 (2004) 3304–3311, for its use with
// equivalent sources). It holds at any distance, including sources millimetres above the road
// and kR ≪ 1, where the asymptotic Weyl–van der Pol form fails, and includes the surface wave.
// β = 0 gives direct + image exactly (the rigid road), β → ∞ direct − image (pressure release).
// The line integral is evaluated by adaptive Gauss–Kronrod quadrature (core/gauss_kronrod.hpp)
// with breaks where the integrand changes fast: near s = 0 on the scale 1/(k|β|), and near
// s = R₂, where |R(s)| has its minimum √(2ZR₂) when Z ≪ r; beyond, |e^{−ikR(s)}| ≤ e^{−k√(s² − r²)}.
#include <complex>

namespace rollnoise {

// G (1/m) at horizontal distance `r` (>= 0, m) between a receiver at height `z_receiver` and a
// source at `z_source` (both >= 0 with z_receiver + z_source > 0, and not coincident), for
// wavenumber k (> 0, 1/m) and admittance `admittance` (Re >= 0; an infinite value: pressure
// release). Bad arguments: std::invalid_argument.
std::complex<double> impedance_plane_green(double k, double r, double z_receiver, double z_source,
                                           std::complex<double> admittance);

// The absorbing road's correction alone, G − direct − image = −(kβ/2π)∫₀^∞ e^{−βt}e^{−ikR}/(kR) dt
// (t = ks), which depends on the heights only through their sum Z = z_receiver + z_source (> 0):
// what reflected_field_table.hpp tabulates. Zero for β = 0; −2·image for β = ∞. The line
// integral to `tolerance` relative to the image's field (1e-13: to rounding, as
// impedance_plane_green; the table's nodes take 1e-10, far below its interpolation's 1e-5).
std::complex<double> impedance_plane_correction(double k, double r, double height, std::complex<double> admittance,
                                                double tolerance = 1e-13);

}  // namespace rollnoise
