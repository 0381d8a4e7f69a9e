// The static residual of a truncated modal sum (src/greens/static_residual.hpp) against Love's
// rectangle (src/greens/tread_compliance.hpp, closed form, none of its code): on an elastic
// half-space, Ĝ(k) = 2(1 − ν²)/(E|k|), the kept modes plus the residual must give the mean
// displacement over a receiver cell under a uniform load on a source cell. The strip is wide and
// long (b = 2 m, L = 2 m) so that its images (sine shapes: antisymmetric at the edges; periodic
// along x) are a metre away from cells millimetres in size.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "gauss_legendre.hpp"
#include "core/case_file.hpp"
#include "greens/static_residual.hpp"
#include "greens/two_layer_factory.hpp"
#include "greens/two_layer_tyre.hpp"
#include "greens/tread_compliance.hpp"

namespace rollnoise {
namespace {

using std::numbers::pi;

TEST(StaticResidual, KeptModesPlusResidualIsLovesRectangleOnAHalfSpace) {
  const double e = 4e6, nu = 0.48;
  const auto halfspace = [&](double kx, double ky) { return 2.0 * (1.0 - nu * nu) / (e * std::hypot(kx, ky)); };
  KeptModes kept;
  kept.circumference = 2.0;
  kept.width = 2.0;
  kept.lateral_shape = LateralShape::sine;
  kept.first_lateral_order = 1;
  kept.lateral_orders = 40;
  kept.orders = 60;
  const int window = 6;
  const double dx = 0.002, dy = 0.007;
  const std::vector<double> y = {1.0 - dy, 1.0, 1.0 + dy};
  const Eigen::MatrixXd residual = static_residual_compliance(kept, halfspace, window, dx, y, dy);
  // The kept modes' own static sum, as the rolling code forms it (modal_tyre.hpp, with the
  // cells' sinc factors).
  const auto sinc = [](double z) { return z == 0.0 ? 1.0 : std::sin(z) / z; };
  const auto kept_sum = [&](double delta_x, double yp, double yq) {
    double sum = 0.0;
    for (int n = 1; n <= kept.lateral_orders; ++n)
      for (int m = 0; m <= kept.orders; ++m) {
        const double km = 2 * pi * m / kept.circumference, kn = n * pi / kept.width;
        const double c = sinc(0.5 * km * dx) * sinc(0.5 * kn * dy);
        sum += (m == 0 ? 1.0 : 2.0) * std::cos(km * delta_x) * halfspace(km, kn) * c * c * std::sin(kn * yp) *
               std::sin(kn * yq) / (kept.circumference * 0.5 * kept.width);
      }
    return sum;
  };
  // Love: the displacement at (x, y) under 1 N spread over the source cell, averaged over the
  // receiver cell by a composite Gauss rule (8 panels × 8 points each way: the self cell's
  // logarithmic edge singularity is integrable).
  const test::GaussRule g = test::gauss_legendre(8);
  const auto love_mean = [&](double cx, double cy) {
    double sum = 0.0;
    const int panels = 8;
    for (int px = 0; px < panels; ++px)
      for (int py = 0; py < panels; ++py)
        for (std::size_t i = 0; i < g.nodes.size(); ++i)
          for (std::size_t j = 0; j < g.nodes.size(); ++j) {
            const double x = cx + dx * ((px + 0.5 + 0.5 * g.nodes[i]) / panels - 0.5);
            const double yy = cy + dy * ((py + 0.5 + 0.5 * g.nodes[j]) / panels - 0.5);
            sum += g.weights[i] * g.weights[j] * 0.25 / (panels * panels) *
                   love_rectangle_displacement(x, yy, 0.5 * dx, 0.5 * dy, e, nu) / (dx * dy);
          }
    return sum;
  };
  double worst = 0.0;
  for (int iq = 0; iq < window; iq += 5)
    for (int jq = 0; jq < 3; ++jq)
      for (int ip = 0; ip < window; ++ip)
        for (int jp = 0; jp < 3; ++jp) {
          const double model = kept_sum((ip - iq) * dx, y[jp], y[jq]) + residual(ip + window * jp, iq + window * jq);
          const double love = love_mean((ip - iq) * dx, y[jp] - y[jq]);
          const double error = std::abs(model / love - 1.0);
          worst = std::max(worst, error);
          EXPECT_LT(error, 0.02) << "receiver (" << ip << ", " << jp << ") source (" << iq << ", " << jq << ")";
        }
  RecordProperty("worst_relative_difference", std::to_string(worst));
  std::printf("static residual + kept modes against Love: worst %.3f %%\n", 100 * worst);
}

}  // namespace
}  // namespace rollnoise

namespace rollnoise {
namespace {

// What the two-layer tyre's static residual assumes (src/greens/rolling_tyre_model.cpp): beyond
// the passenger file's table (|k| from 450 rad/m, wavelengths under 14 mm) the tread carries the
// static response, so it depends on |k| alone: along the circumference, across and along the
// diagonal it agrees within 1 % (the belt's orthotropy no longer shows).
TEST(StaticResidual, PassengerTwoLayerIsIsotropicBeyondItsTable) {
  const TwoLayerParameters p =
      read_two_layer_tyre(CaseFile::load_model(std::string(ROLLNOISE_SOURCE_DIR) + "/models/tyres/passenger_205_55R16_two_layer.toml").top());
  const TwoLayerTyre tyre(p);
  double worst = 0.0;
  for (const double k : {450.0, 800.0, 1600.0, 4000.0, 16000.0}) {
    const double diagonal = tyre.wavenumber_compliance(k / std::sqrt(2.0), k / std::sqrt(2.0), 0.0)(2, 2).real();
    for (const double other : {tyre.wavenumber_compliance(k, 0.0, 0.0)(2, 2).real(),
                               tyre.wavenumber_compliance(0.0, k, 0.0)(2, 2).real()}) {
      worst = std::max(worst, std::abs(other / diagonal - 1.0));
      EXPECT_LT(std::abs(other / diagonal - 1.0), 0.01) << "k = " << k;
    }
  }
  std::printf("two-layer static compliance beyond the table: direction changes it by at most %.3f %%\n", 100 * worst);
}

}  // namespace
}  // namespace rollnoise
