#pragma once
// The two-layer tyre's cross-section per wavenumber (Larsson & Kropp, JSV 253(4) 2002 889–908;
// MODEL.md §4): from the inside out
//   z = 0          the belt's inner face, on an elastic foundation (air cavity, sidewalls) and
//                  carrying the inflation pre-tension;
//   0 < z < h_b    the belt: thin, stiff, homogeneous, orthotropic (steel-cord plies);
//   h_b < z < h    the tread: soft, isotropic, viscoelastic rubber, bonded to the belt;
//   z = h          the tread surface, where the road loads the tyre.
// z points outward, away from the axle. For a load e^{i(k_x x + k_y y + ωt)} on the tread
// surface, surface_compliance() returns the 3×3 matrix Ĝ with û = Ĝ·τ̂ (displacement per traction,
// m/Pa), components (x, y, z). The normal–normal entry Ĝ_zz is the same for the contact's
// convention (force and displacement both towards the axle).
//
// Inner face: the foundation and the tension act on the normal displacement only,
//   f_z = −(s_f·ψ_f(ω) + T_x k_x² + T_y k_y²)·u_z,  f_x = f_y = 0,
// the tension's term being the restoring force of a membrane under T_x, T_y (it adds
// T_x k_x² + T_y k_y² to the belt's normal stiffness per area; applying it at the inner face
// rather than through the belt is exact to O((k h_b)²) for a thin belt). The belt and tread
// stiffnesses (layer_stiffness.hpp) are joined at the bonded interface (continuous displacement
// and traction) and condensed from the inside out:
//   Z_1 = K^b_tt − K^b_tb (K^b_bb + S)^{-1} K^b_bt,   Z_2 = K^t_tt − K^t_tb (K^t_bb + Z_1)^{-1} K^t_bt,
//   Ĝ = Z_2^{-1}.
// Each layer's moduli carry their own causal factor ψ(ω) (causal_modulus.hpp); the foundation
// carries ψ_f of its loss factor; the tension is lossless.
//
// At k = 0 and ω = 0 the in-plane motion is a free translation: Ĝ_xx and Ĝ_yy are +∞ there,
// the couplings to them 0, and Ĝ_zz stays finite (the normal problem decouples exactly at k = 0).
#include <complex>

#include <Eigen/Core>

#include "greens/causal_modulus.hpp"
#include "greens/layer_stiffness.hpp"
#include "greens/orthotropic_material.hpp"

namespace rollnoise {

struct ElasticLayer {
  OrthotropicStiffness stiffness;  // at the reference frequency (storage moduli)
  double density = 0.0;            // kg/m³
  double thickness = 0.0;          // m
  double loss_factor = 0.0;        // at the reference frequency (CausalModulus)
};

class TwoLayerStack {
 public:
  // std::invalid_argument for non-physical values.
  TwoLayerStack(const ElasticLayer& belt, const ElasticLayer& tread, double tension_x, double tension_y,
                double foundation_stiffness, double foundation_loss_factor);

  const ElasticLayer& belt() const noexcept { return belt_; }
  const ElasticLayer& tread() const noexcept { return tread_; }

  // Ĝ(k_x, k_y, ω) of the header, m/Pa. ω may be complex with Im ω ≤ 0 (exponential window).
  Eigen::Matrix3cd surface_compliance(double kx, double ky, std::complex<double> omega) const;
  // The inner-face normal stiffness per area s_f·ψ_f(ω) + T_x k_x² + T_y k_y², N/m³.
  std::complex<double> inner_face_stiffness(double kx, double ky, std::complex<double> omega) const;

  // The pieces of surface_compliance: each layer's dynamic stiffness at (k_x, k_y, ω), and Ĝ
  // from them with this stack's inner face. A caller that varies one layer's parameters at a
  // time (calibration's finite differences) reuses the other layer's stiffness.
  LayerStiffness belt_stiffness(double kx, double ky, std::complex<double> omega) const;
  LayerStiffness tread_stiffness(double kx, double ky, std::complex<double> omega) const;
  Eigen::Matrix3cd surface_compliance(const LayerStiffness& belt, const LayerStiffness& tread, double kx, double ky,
                                      std::complex<double> omega) const;

 private:
  ElasticLayer belt_;
  ElasticLayer tread_;
  double tension_x_ = 0.0;
  double tension_y_ = 0.0;
  double foundation_ = 0.0;
  CausalModulus belt_modulus_;
  CausalModulus tread_modulus_;
  CausalModulus foundation_modulus_;
};

}  // namespace rollnoise
