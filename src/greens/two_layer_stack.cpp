#include "greens/two_layer_stack.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

namespace rollnoise {
namespace {

using cd = std::complex<double>;

void check_layer(const ElasticLayer& layer, const std::string& name) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(layer.density)) throw std::invalid_argument(name + "_density must be finite and > 0");
  if (!positive(layer.thickness)) throw std::invalid_argument(name + "_thickness must be finite and > 0");
  const OrthotropicStiffness& s = layer.stiffness;
  for (const double c : {s.c11, s.c22, s.c33, s.c44, s.c55, s.c66}) {
    if (!positive(c)) throw std::invalid_argument(name + " stiffnesses must be finite and > 0");
  }
}

// Z_top = K_tt − K_tb (K_bb + Z_below)^{-1} K_bt: the layer's top-face impedance with what lies
// below it condensed out.
Eigen::Matrix3cd condense(const LayerStiffness& layer, const Eigen::Matrix3cd& below) {
  const Matrix6cd k = layer.matrix();
  const Eigen::Matrix3cd bb = k.block<3, 3>(0, 0) + below;
  return k.block<3, 3>(3, 3) - k.block<3, 3>(3, 0) * bb.partialPivLu().solve(k.block<3, 3>(0, 3));
}

}  // namespace

TwoLayerStack::TwoLayerStack(const ElasticLayer& belt, const ElasticLayer& tread, double tension_x,
                             double tension_y, double foundation_stiffness, double foundation_loss_factor)
    : belt_(belt),
      tread_(tread),
      tension_x_(tension_x),
      tension_y_(tension_y),
      foundation_(foundation_stiffness),
      belt_modulus_(belt.loss_factor),
      tread_modulus_(tread.loss_factor),
      foundation_modulus_(foundation_loss_factor) {
  check_layer(belt_, "belt");
  check_layer(tread_, "tread");
  const auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!non_negative(tension_x)) throw std::invalid_argument("tension_x must be finite and >= 0");
  if (!non_negative(tension_y)) throw std::invalid_argument("tension_y must be finite and >= 0");
  if (!non_negative(foundation_stiffness)) throw std::invalid_argument("foundation_stiffness must be finite and >= 0");
}

cd TwoLayerStack::inner_face_stiffness(double kx, double ky, cd omega) const {
  return foundation_ * foundation_modulus_.factor(omega) + tension_x_ * kx * kx + tension_y_ * ky * ky;
}

LayerStiffness TwoLayerStack::belt_stiffness(double kx, double ky, cd omega) const {
  return layer_stiffness(belt_.stiffness, belt_modulus_.factor(omega), belt_.density, belt_.thickness, kx, ky, omega);
}

LayerStiffness TwoLayerStack::tread_stiffness(double kx, double ky, cd omega) const {
  return layer_stiffness(tread_.stiffness, tread_modulus_.factor(omega), tread_.density, tread_.thickness, kx, ky,
                         omega);
}

Eigen::Matrix3cd TwoLayerStack::surface_compliance(double kx, double ky, cd omega) const {
  return surface_compliance(belt_stiffness(kx, ky, omega), tread_stiffness(kx, ky, omega), kx, ky, omega);
}

Eigen::Matrix3cd TwoLayerStack::surface_compliance(const LayerStiffness& belt, const LayerStiffness& tread, double kx,
                                                   double ky, cd omega) const {
  const cd inner = inner_face_stiffness(kx, ky, omega);
  if (kx == 0.0 && ky == 0.0 && omega == 0.0) {
    // A free in-plane translation: only the normal problem, which decouples exactly at k = 0.
    const auto zz = [](const LayerStiffness& l, cd below) {
      const Matrix6cd k = l.matrix();
      return k(5, 5) - k(5, 2) * k(2, 5) / (k(2, 2) + below);
    };
    Eigen::Matrix3cd g = Eigen::Matrix3cd::Zero();
    const double infinity = std::numeric_limits<double>::infinity();
    g(0, 0) = infinity;
    g(1, 1) = infinity;
    g(2, 2) = 1.0 / zz(tread, zz(belt, inner));
    return g;
  }
  Eigen::Matrix3cd s = Eigen::Matrix3cd::Zero();
  s(2, 2) = inner;
  const Eigen::Matrix3cd z2 = condense(tread, condense(belt, s));
  return z2.partialPivLu().inverse();
}

}  // namespace rollnoise
