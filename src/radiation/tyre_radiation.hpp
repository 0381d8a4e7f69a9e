#pragma once
// The radiation stage of a rolling run (MODEL.md §5): the normal velocity of the tyre's surface
// over time in, the sound pressure over time at the receivers and the radiated sound power
// spectrum out.
//
// Method. The velocities are Fourier transformed (zero-padded, so the convolution with the
// receivers' responses is linear, not circular); at each frequency bin the equivalent-source
// model of the tyre over the rigid road (equivalent_sources.hpp, tyre_surface_mesh.hpp) maps
// them to pressures and power. Solving that model costs seconds per frequency, so it is solved
// at anchor frequencies, in parallel, and interpolated between them:
//  - receiver pressures through TransferTable (the propagation delay taken out, so the signals
//    come out in retarded time: sample n is the sound the tyre emitted at step n);
//  - sound power as W = ½ qᴴSq (EquivalentSources::power_matrix) for the bin's own velocities,
//    with the radiation operator interpolated linearly between the two anchors around the bin:
//    each anchor's solve is applied to every bin within one anchor spacing of it, weighted by
//    the hat function.
// The steady part of the velocities (the mean of each point) carries no sound and is removed.
// Below the lowest anchor and above the highest, nothing is radiated.
//
// Determinism: every anchor is solved the same way whatever thread solves it, and the results
// are combined in anchor order, so the numbers do not depend on the thread count.
#include <vector>

#include <Eigen/Core>

#include "radiation/equivalent_sources.hpp"
#include "radiation/tyre_surface_mesh.hpp"

namespace rollnoise {

class ProgressReporter;

struct TyreRadiationSettings {
  TyreSurfaceMeshSpec mesh;
  Medium medium;
  double max_frequency_hz = 3000.0;   // highest anchor (capped just below the Nyquist frequency)
  double anchor_spacing_hz = 100.0;   // anchors at 20, 50, then every spacing up to the maximum
  double regularisation = 1e-10;      // Tikhonov λ relative to the largest singular value
  int threads = 0;                    // parallel anchor solves; 0: the machine's cores
};

struct RadiatedSound {
  double sample_rate = 0.0;       // Hz, that of the velocities
  double lowest_hz = 0.0;         // the band that was computed
  double highest_hz = 0.0;
  Eigen::MatrixXd pressure;       // samples × receivers, Pa, in retarded time
  Eigen::VectorXd frequency_hz;   // the transform's bins
  Eigen::VectorXd sound_power_w;  // power in each bin, W: they sum to the mean radiated power
  Eigen::VectorXd delays_s;       // each receiver's propagation delay from the wheel centre
};

class TyreRadiation {
 public:
  // receivers: 3 × R positions in the mesh's coordinates (tyre_surface_mesh.hpp).
  TyreRadiation(const TyreRadiationSettings& settings, Eigen::Matrix3Xd receivers);

  const TyreSurfaceMesh& mesh() const noexcept { return mesh_; }
  // The anchor frequencies used for a velocity signal sampled at `sample_rate`.
  std::vector<double> anchors(double sample_rate) const;

  // surface_velocity: samples × A normal velocities (m/s, outward) of the first A collocation
  // points of the mesh (A = all of them, or mesh().tread_points: the sidewalls at rest), sampled
  // at `sample_rate`. progress (optional) counts anchors.
  RadiatedSound radiate(const Eigen::MatrixXd& surface_velocity, double sample_rate,
                        ProgressReporter* progress = nullptr) const;

 private:
  TyreRadiationSettings settings_;
  TyreSurfaceMesh mesh_;
  EquivalentSources model_;
  Eigen::Matrix3Xd receivers_;
  Eigen::Vector3d centre_;
};

}  // namespace rollnoise
