// The tread's local compliance per contact cell (issue 11 notes): the static displacement of a
// cell of the 80 km/h contact grid (1.95 × 7 mm) under 1 N spread over it, at the middle of the
// belt, for the two-layer tyre (its modes up to the model file's orders plus the static residual
// beyond, as the rolling code forms it), against the plate file's Winkler tread (1/(k·A)).
//   cell_compliance TWO_LAYER_MODEL.toml [winkler_N_per_m3] [dx_m] [dy_m]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "core/case_file.hpp"
#include "greens/static_residual.hpp"
#include "greens/two_layer_factory.hpp"
#include "greens/two_layer_tyre.hpp"

int main(int argc, char** argv) {
  using namespace rollnoise;
  if (argc < 2) {
    std::fprintf(stderr, "usage: cell_compliance TWO_LAYER_MODEL.toml [winkler] [dx] [dy]\n");
    return 2;
  }
  const TwoLayerParameters p = read_two_layer_tyre(CaseFile::load_model(argv[1]).top());
  const double winkler = argc > 2 ? std::atof(argv[2]) : 5e8;
  const double dx = argc > 3 ? std::atof(argv[3]) : 2 * std::numbers::pi * p.radius / 1016;
  const double dy = argc > 4 ? std::atof(argv[4]) : 0.007;
  const TwoLayerTyre tyre(p);
  const auto table = tyre.response(0.0);
  const double length = tyre.circumference();
  const double y = 0.5 * p.width;
  const auto sinc = [](double z) { return z == 0.0 ? 1.0 : std::sin(z) / z; };
  double kept = 0.0;
  for (int n = 1; n <= p.lateral_modes; ++n)
    for (int m = 0; m <= p.circumferential_modes; ++m) {
      const double c = sinc(0.5 * tyre.wavenumber_x(m) * dx) * sinc(0.5 * tyre.wavenumber_y(n) * dy);
      const double phi = std::sin(tyre.wavenumber_y(n) * y);
      kept += (m == 0 ? 1.0 : 2.0) * table.modal_compliance(m, n)(2, 2).real() * c * c * phi * phi / tyre.modal_norm(n);
    }
  KeptModes k{length, p.width, LateralShape::sine, 1, p.lateral_modes, p.circumferential_modes};
  const std::vector<double> ys = {y};
  const Eigen::MatrixXd residual = static_residual_compliance(
      k, [&](double kx, double ky) { return tyre.wavenumber_compliance(kx, ky, 0.0)(2, 2).real(); }, 1, dx, ys, dy);
  const double total = kept + residual(0, 0);
  std::printf("cell %.2f x %.2f mm at mid-belt, 1 N spread over it (static):\n", dx * 1e3, dy * 1e3);
  std::printf("  two-layer: kept modes %.3e m/N + residual %.3e m/N = %.3e m/N (stiffness %.3e N/m)\n", kept,
              residual(0, 0), total, 1.0 / total);
  std::printf("  Winkler %.3g N/m^3: %.3e m/N (stiffness %.3e N/m); two-layer / Winkler stiffness %.2f\n", winkler,
              1.0 / (winkler * dx * dy), winkler * dx * dy, 1.0 / total / (winkler * dx * dy));
  return 0;
}
