#pragma once
// The two-layer elastic tyre (Larsson & Kropp, JSV 253(4) 2002 889–908; the seed paper's §5
// tyre; MODEL.md §4): belt and tread as two bonded 3-D elastic layers (two_layer_stack.hpp),
// unrolled to a flat strip — curvature neglected — of length L = 2πR (periodic) and width b,
// with the belt under the inflation pre-tension on an elastic foundation.
//
// Side conditions at the belt edges y = 0 and y = b, for both layers, through their whole
// thickness. They are the conditions under which the 3-D field separates exactly into one
// trigonometric function of y per component (an orthotropic solid with an axis along y keeps
// u_x, u_z and u_y of opposite parity):
//   simply_supported: u_x = u_z = 0 and σ_yy = 0 at y = 0, b (the edges are held against
//     normal and circumferential motion and may rotate freely about x: the 3-D form of a
//     simply supported plate edge). Shapes u_x, u_z ∝ sin(k_n y), u_y ∝ cos(k_n y),
//     k_n = nπ/b, n = 1 … N.
//   sliding: u_y = 0 and σ_xy = σ_zy = 0 at y = 0, b (the edges translate freely along x and
//     z, without force, but keep their slope: ∂u_z/∂y = 0, so they do not rotate — a guided
//     edge). Shapes u_x, u_z ∝ cos(k_n y), u_y ∝ sin(k_n y), n = 0 … N − 1; n = 0 is the
//     uniform lateral shape.
//
// Modes e^{i k_m x} × (the shapes), k_m = 2πm/L, m = −M … M. For each mode the 3×3 modal
// compliance H(m, n, ω) (displacement amplitudes of the shapes per traction amplitudes of the
// same shapes) follows from the exponential-form Ĝ(k_m, k_n, ω) of the stack by
//   simply_supported: H = D⁻¹ĜD,  sliding: H = DĜD⁻¹,  D = diag(1, i, 1)
// (the sine and cosine of y are sums of e^{±ik_n y}; the y mirror symmetry of the layers makes
// the two halves agree), and H(−m) = Π H(m) Π with Π = diag(−1, 1, 1) (x mirror).
// Receptance between a receiver r and a source s (m/N), components i, j:
//   α_ij = Σ_n Σ_m H_ij(m, n, ω) e^{ik_m(x_r − x_s)} φ_i,n(y_r) φ_j,n(y_s) / (L·N_n)
// with N_n = ∫₀ᵇ φ² dy = b/2 (b for the sliding n = 0). A cell of length ℓ and width w
// multiplies each mode by sinc(k_m ℓ/2)·sinc(k_n w/2) (the mean of e^{ik_m x}·sin or cos over
// it). The receptance depends on x_r − x_s only (rotation invariance) and α_ij(r, s) = α_ji(s, r)
// (reciprocity; tests/greens/test_two_layer_tyre.cpp).
//
// Loss: each layer's moduli carry a causal nearly-constant-loss factor (causal_modulus.hpp),
// which makes the time-domain Green's functions causal (two_layer_greens_functions.hpp).
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "greens/orthotropic_material.hpp"
#include "greens/surface_receptance_model.hpp"
#include "greens/two_layer_stack.hpp"

namespace rollnoise {

enum class SideCondition { simply_supported, sliding };

struct TwoLayerParameters {
  double radius = 0.0;  // R, m (L = 2πR)
  double width = 0.0;   // b, m
  // The belt: orthotropic, x circumferential, y lateral, z normal.
  OrthotropicConstants belt;
  double belt_thickness = 0.0;    // m
  double belt_density = 0.0;      // kg/m³
  double belt_loss_factor = 0.0;  // η at 1 kHz
  // The tread: isotropic rubber.
  double tread_thickness = 0.0;      // m
  double tread_density = 0.0;        // kg/m³
  double tread_youngs_modulus = 0.0;  // Pa, storage modulus at 1 kHz
  double tread_poisson_ratio = 0.0;
  double tread_loss_factor = 0.0;  // η at 1 kHz
  double tension_x = 0.0;               // N/m
  double tension_y = 0.0;               // N/m
  double foundation_stiffness = 0.0;    // N/m³
  double foundation_loss_factor = 0.0;  // η at 1 kHz (same causal form)
  int circumferential_modes = 0;        // M: m = −M … M
  int lateral_modes = 0;                // N lateral orders
  SideCondition side_condition = SideCondition::simply_supported;
  // The contact geometry (not part of the layer solution): the tread's crown radius across the
  // width (0: flat) and the width that meets the road (0: the whole width), as the plate file's.
  double crown_radius = 0.0;  // m
  double tread_width = 0.0;   // m
};

class TwoLayerTyre;

// The tyre at one frequency: the modal compliances of all modes, then cheap modal sums. It
// refers to its tyre, which must outlive it.
class TwoLayerResponse final : public SurfaceResponse {
 public:
  std::complex<double> frequency() const override { return omega_; }
  std::complex<double> receptance(const SurfaceLocation& receiver, const SurfaceLocation& source,
                                  SurfaceDirection response = SurfaceDirection::z,
                                  SurfaceDirection load = SurfaceDirection::z) const override;
  // H(m, n) for m = 0 … M and the tyre's lateral orders.
  const Eigen::Matrix3cd& modal_compliance(int m, int n) const;

 private:
  friend class TwoLayerTyre;
  TwoLayerResponse(const TwoLayerTyre& tyre, std::complex<double> omega);
  const TwoLayerTyre* tyre_;
  std::complex<double> omega_;
  std::vector<Eigen::Matrix3cd> table_;  // index (n − first)·(M + 1) + m
};

class TwoLayerTyre final : public SurfaceReceptanceModel {
 public:
  // std::invalid_argument naming the parameter for non-physical values.
  explicit TwoLayerTyre(const TwoLayerParameters& parameters);

  const TwoLayerParameters& parameters() const noexcept { return p_; }
  const TwoLayerStack& stack() const noexcept { return stack_; }

  std::string name() const override { return "two_layer"; }
  double circumference() const override { return length_; }
  double width() const override { return p_.width; }

  // Lateral orders n = first_lateral_order() … last_lateral_order() (1 … N or 0 … N − 1).
  int first_lateral_order() const noexcept;
  int last_lateral_order() const noexcept;
  double wavenumber_x(int m) const noexcept;  // k_m = 2πm/L
  double wavenumber_y(int n) const noexcept;  // k_n = nπ/b
  // φ_{d,n}(y): the lateral shape of component d.
  double lateral_shape(SurfaceDirection d, int n, double y) const noexcept;
  // L·N_n, m².
  double modal_norm(int n) const noexcept;

  // H(m, n, ω) of the header (m may be negative).
  Eigen::Matrix3cd modal_compliance(int m, int n, std::complex<double> omega) const;
  // Ĝ(k_x, k_y, ω) of the stack, for any wavenumbers.
  Eigen::Matrix3cd wavenumber_compliance(double kx, double ky, std::complex<double> omega) const;

  TwoLayerResponse response(std::complex<double> omega) const { return TwoLayerResponse(*this, omega); }
  std::unique_ptr<SurfaceResponse> at(std::complex<double> omega) const override;

 private:
  TwoLayerParameters p_;
  TwoLayerStack stack_;
  double length_ = 0.0;
};

// The stack of the parameters (belt and tread layers, tension, foundation); std::invalid_argument
// naming the parameter for non-physical values.
TwoLayerStack make_two_layer_stack(const TwoLayerParameters& parameters);

}  // namespace rollnoise
