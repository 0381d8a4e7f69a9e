#pragma once
// Point monopoles of known volume flow radiating over the road: the air pumped out of the contact
// patch (contact/air_pumping.hpp; docs/physics/air-pumping.md). A monopole of volume flow q(t)
// (m³/s) makes p(x, t) = ρ·q̇(t − r/c)/(4πr) in free field (Hayden 1971), and over a rigid road
// its image doubles it where source and receiver are near the road. In the frequency domain
// (e^{+iωt}, the library's convention): P(ω) = iωρ·Q(ω)·G(x, s, k), with G the same Green's
// function as the vibration's equivalent sources take (MonopoleGreen: the hook through which a
// road with an impedance replaces the rigid one).
//
// The sources radiate into the half-space as if the tyre were not there: the horn between tread
// and road and the tyre's shadow are left out (docs/physics/air-pumping.md, "Limits").
#include <complex>
#include <functional>

#include <Eigen/Core>

#include "radiation/equivalent_sources.hpp"

namespace rollnoise {

// G(receiver, source, k) in the library's convention, e^{−ikr}/(4πr) plus the road's reflection.
using MonopoleGreen = std::function<std::complex<double>(const Eigen::Vector3d&, const Eigen::Vector3d&, double)>;

// The rigid road: free field and image (helmholtz_green with rigid_plane).
MonopoleGreen rigid_road_green();

struct MonopoleSources {
  Eigen::Matrix3Xd positions;  // m, mesh coordinates (x along travel, y across, z up from the road)
  Eigen::MatrixXd flows;       // samples × sources, m³/s; sample n is the mean flow over
                               // [t_n − Δt, t_n] (a difference of volumes), i.e. at t_n − Δt/2
};

struct MonopoleSound {
  Eigen::MatrixXd pressure;        // samples × receivers, Pa
  Eigen::VectorXd frequency_hz;    // the bins the power is given on (the caller's)
  Eigen::VectorXd sound_power_w;   // per bin, W: they sum to the mean power in the band
  double total_power_w = 0.0;
};

// The pressure at each receiver (3 × R, mesh coordinates), with each receiver's delay
// `delays_s` (R) taken off as the vibration's is (the retarded time of tyre_radiation.hpp), in
// the band [lowest_hz, highest_hz] (the vibration's band; the flows' mean is no sound); and the
// sound power of the sources, W = ½ωρ·Σ_ab Re(Q_a Q_b*)·(−Im G(s_a, s_b)), gathered onto the
// bins `frequency_hz` (each of the own transform's bins to the nearest; empty: none). The record
// is zero-padded to at least twice its length, as the vibration's transform is padded.
MonopoleSound radiate_monopoles(const MonopoleSources& sources, double sample_rate, const Eigen::Matrix3Xd& receivers,
                                const Eigen::VectorXd& delays_s, double lowest_hz, double highest_hz,
                                const Eigen::VectorXd& frequency_hz, const Medium& medium, const MonopoleGreen& green);

}  // namespace rollnoise
