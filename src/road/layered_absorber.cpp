#include "road/layered_absorber.hpp"

#include <array>
#include <stdexcept>
#include <utility>

namespace rollnoise {
namespace {

using Complex = std::complex<double>;
using Matrix2 = std::array<std::array<Complex, 2>, 2>;

Matrix2 multiply(const Matrix2& a, const Matrix2& b) {
  Matrix2 c{};
  for (int r = 0; r < 2; ++r)
    for (int s = 0; s < 2; ++s) c[r][s] = a[r][0] * b[0][s] + a[r][1] * b[1][s];
  return c;
}

}  // namespace

LayeredAbsorber::LayeredAbsorber(std::vector<PorousLayer> layers, AirProperties air)
    : layers_(std::move(layers)), air_(air) {
  if (layers_.empty()) throw std::invalid_argument("LayeredAbsorber: at least one layer");
}

Complex LayeredAbsorber::normalised_impedance(double frequency) const {
  // (p, v) at the top of a layer = T (p, v) at its bottom, v the normal flux velocity (downward):
  //   T = [[cos kd, i Z_c sin kd], [i sin kd / Z_c, cos kd]]   (e^{+iωt})
  // and v = 0 on the rigid base, so Z_s = (T₁T₂…Tₙ)₁₁ / (T₁T₂…Tₙ)₂₁.
  Matrix2 total{{{Complex(1.0), Complex(0.0)}, {Complex(0.0), Complex(1.0)}}};
  const Complex i(0.0, 1.0);
  for (const PorousLayer& layer : layers_) {
    const PorousLayerWave wave = porous_layer_wave(layer, air_, frequency);
    const Complex kd = wave.wavenumber * layer.thickness;
    const Complex c = std::cos(kd), s = std::sin(kd);
    const Matrix2 t{{{c, i * wave.characteristic_impedance * s}, {i * s / wave.characteristic_impedance, c}}};
    total = multiply(total, t);
  }
  return total[0][0] / total[1][0] / (air_.density * air_.sound_speed);
}

double LayeredAbsorber::absorption_coefficient(double frequency) const {
  const Complex z = normalised_impedance(frequency);
  return 1.0 - std::norm((z - 1.0) / (z + 1.0));
}

}  // namespace rollnoise
