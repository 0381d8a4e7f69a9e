#pragma once
// Contact of an elastic half-space (the tread rubber) pressed onto a rigid rough surface (the
// road's fine texture) on a fine regular grid: the boundary-element contact that per-cell contact
// laws are made from (Andersson & Kropp, JSV 318 (2008) 296-312).
//
// Discretisation. Pressure uniform over each grid cell (dx × dy); the surface displacement at a
// cell's centre from unit pressure on another cell is Love's (1929) rectangle solution
// (love_rectangle_displacement, greens/tread_compliance.hpp), E* = E / (1 − ν²) for a rigid
// road. The product of those influence coefficients with the pressures is a 2-D convolution,
// computed by FFT on the grid zero-padded to twice its size (no periodic images).
//
// Problem. The rubber's undeformed flat face stands at z = max(h) − δ: δ is the approach from
// the first touch of the highest point. With the road's overlap o_i = h_i − (max h − δ) and the
// rubber's displacement u = K p (into the rubber, positive), the contact conditions are
// p_i ≥ 0, u_i − o_i ≥ 0, p_i (u_i − o_i) = 0: the minimum of ½ pᵀKp − oᵀp over p ≥ 0.
// Solved by the constrained conjugate gradients of Polonsky & Keer (Wear 231 (1999) 206-219),
// the displacement-controlled form (no mean-gap correction), to a relative change of the
// pressures below `tolerance`.
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace rollnoise {

struct HalfspaceContactResult {
  std::vector<double> pressure;  // Pa, per grid cell, row-major (i along x, j along y: i·ny + j)
  double force = 0.0;            // N
  double contact_area = 0.0;     // m², the cells with pressure > 0
  int iterations = 0;
  bool converged = false;
};

class HalfspaceTextureContact {
 public:
  // An nx × ny grid of cells dx × dy (m); the rubber's E (Pa) and ν. Plans the FFTs once.
  HalfspaceTextureContact(std::size_t nx, std::size_t ny, double dx, double dy, double youngs_modulus,
                          double poisson_ratio);
  ~HalfspaceTextureContact();
  HalfspaceTextureContact(const HalfspaceTextureContact&) = delete;
  HalfspaceTextureContact& operator=(const HalfspaceTextureContact&) = delete;

  // `heights`: the road (m, upward) at the cell centres, nx·ny values row-major; `approach` δ ≥ 0.
  HalfspaceContactResult solve(std::span<const double> heights, double approach, double tolerance = 1e-9,
                               int max_iterations = 2000) const;

  // u = K p: the surface displacement (m, into the rubber) at every cell centre from `pressure`.
  void displacement(std::span<const double> pressure, std::span<double> out) const;

 private:
  struct Fft;
  std::size_t nx_, ny_;
  double dx_, dy_;
  std::unique_ptr<Fft> fft_;
};

}  // namespace rollnoise
