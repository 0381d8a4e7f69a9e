// The derivatives the fit relies on, checked against finite differences: the sdof models'
// automatic derivatives (ceres::Jet), the plate's analytic modal-sum derivatives (whose value
// must also equal KroppPlate::receptance), the generic central differences for any other
// GreensModel, the two-layer tyre's node-wise central differences (and its kept modes plus
// interpolated tail against the tyre's own mode-by-mode sum), and the whole residual (complex
// log, mass loading, log-space unknowns) through ceres::GradientChecker.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include <ceres/gradient_checker.h>
#include <toml++/toml.h>

#include "calibrate/frf_residual.hpp"
#include "calibrate/greens_model_calibration.hpp"
#include "calibrate/plate_calibration.hpp"
#include "calibrate/sdof_calibration.hpp"
#include "calibrate/two_layer_calibration.hpp"
#include "core/case_file.hpp"
#include "core/error.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/two_layer_factory.hpp"
#include "greens/passenger_plate.hpp"

namespace rollnoise {
namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

// The passenger tyre of models/tyres/passenger_205_55R16.toml, with fewer modes where a test
// needs speed more than convergence.
using test::passenger_plate;

// The largest error of `gradient` against central differences of α in each parameter's log,
// relative to |α|: max_k |p_k·∂α/∂p_k − FD|/|α|. FD extrapolates central differences with
// steps h and h/2 in log p (Richardson), h such that α changes by about 1e-3 of itself:
// truncation ∝ h⁴, rounding ≈ 1e-16/h.
// With `of_larger`, the error is rated against max(|α|, |p_k·∂α/∂p_k|) instead: near a sharp
// resonance, where α changes by many times itself per unit of log p, a difference quotient's
// error grows with the derivative.
double log_gradient_error(const ReceptanceFunction& f, const std::vector<double>& values, double omega,
                          const std::vector<std::size_t>& wanted, bool print = false, bool of_larger = false) {
  std::vector<std::complex<double>> gradient(values.size());
  const std::complex<double> alpha = f.evaluate(values, omega, gradient.data(), wanted);
  double worst = 0.0;
  for (std::size_t k : wanted) {
    const auto central = [&](double h) {
      std::vector<double> up = values, down = values;
      up[k] *= std::exp(h);
      down[k] *= std::exp(-h);
      return (f.evaluate(up, omega, nullptr, {}) - f.evaluate(down, omega, nullptr, {})) / (2.0 * h);
    };
    // Richardson's extrapolation of two central differences: truncation error ∝ h⁴. The step
    // changes α by about 1e-3 of itself, also near a sharp resonance where α is very sensitive.
    const double sensitivity = std::abs(values[k] * gradient[k]) / std::abs(alpha);
    const double h = 1e-3 / std::max(1.0, sensitivity);
    const std::complex<double> fd = (4.0 * central(h / 2.0) - central(h)) / 3.0;
    const double scale = of_larger ? std::max(std::abs(alpha), std::abs(fd)) : std::abs(alpha);
    const double error = std::abs(values[k] * gradient[k] - fd) / scale;
    if (print) std::printf("    k=%zu  |p dα/dp|/|α| = %.3e  error %.2e\n", k, std::abs(fd) / std::abs(alpha), error);
    worst = std::max(worst, error);
  }
  return worst;
}

std::vector<std::size_t> all(std::size_t n) {
  std::vector<std::size_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = i;
  return v;
}

TEST(SdofCalibration, JetDerivativesMatchFiniteDifferences) {
  // The paper's Table 1 (over-damped) and an under-damped variant, point and transfer.
  const SdofParameters table1{1.0, 50.0, 500.0, 1e5};
  const SdofParameters light{0.5, 2.0, 2e4, 3e5};
  double worst = 0.0;
  for (const SdofParameters& p : {table1, light}) {
    const SdofCalibration model(p, true, 0.4, 0.01);
    const auto point = model.receptance({});
    const auto transfer = model.receptance({{0.01, 0.0}, {0.0, 0.0}});
    const std::vector<double> values = model.file_values();
    for (double hz : {0.5, 3.0, 30.0, 300.0, 3000.0}) {
      worst = std::max(worst, log_gradient_error(*point, values, two_pi * hz, all(4)));
      worst = std::max(worst, log_gradient_error(*transfer, values, two_pi * hz, all(5)));
    }
  }
  std::printf("  sdof Jet derivatives vs central differences: max relative error %.2e\n", worst);
  EXPECT_LT(worst, 1e-9);
}

TEST(SdofCalibration, ReceptanceIsTheModelsOwn) {
  const SdofParameters p{1.0, 50.0, 500.0, 1e5};
  const SdofModel reference(p, 0.4, 0.01);
  const SdofCalibration model(p, true, 0.4, 0.01);
  const std::vector<double> values = model.file_values();
  for (double omega : {1.0, 100.0, 1e4}) {
    const Eigen::MatrixXcd alpha = reference.receptance(omega);
    EXPECT_NEAR(std::abs(model.receptance({})->evaluate(values, omega, nullptr, {}) - alpha(0, 0)), 0.0,
                1e-14 * std::abs(alpha(0, 0)));
    EXPECT_NEAR(std::abs(model.receptance({{0.01, 0}, {0, 0}})->evaluate(values, omega, nullptr, {}) - alpha(1, 0)),
                0.0, 1e-14 * std::abs(alpha(1, 0)));
  }
  // Positions that are not contact points are refused.
  EXPECT_THROW(model.receptance({{0.02, 0}, {0, 0}}), InputError);
  EXPECT_THROW(SdofCalibration(p, false, 0.0, 0.0).receptance({{0.01, 0}, {0, 0}}), InputError);
}

TEST(PlateCalibration, ReceptanceEqualsKroppPlate) {
  const PlateParameters p = passenger_plate(64, 9);
  const PlateCalibration model(p);
  const KroppPlate plate(p);
  double worst = 0.0;
  for (const FrfPoints& points : {FrfPoints{{0.0, 0.09}, {0.0, 0.09}}, FrfPoints{{0.1, 0.06}, {0.0, 0.09}},
                                  FrfPoints{{-0.5, 0.0}, {3.0, 0.18}}, FrfPoints{{1.9, 0.02}, {0.0, 0.15}}}) {
    const auto f = model.receptance(points);
    for (double hz : {1.0, 50.0, 82.0, 115.0, 400.0, 2500.0}) {
      const double omega = two_pi * hz;
      const std::complex<double> expected =
          plate.receptance(points.response.x - points.excitation.x, points.response.y, points.excitation.y, omega);
      const std::complex<double> got = f->evaluate(model.file_values(), omega, nullptr, {});
      if (expected == 0.0) {
        EXPECT_EQ(got, 0.0);
        continue;
      }
      worst = std::max(worst, std::abs(got - expected) / std::abs(expected));
    }
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_THROW(model.receptance({{0.0, 0.2}, {0.0, 0.09}}), InputError) << "y beyond the width";
  EXPECT_THROW(model.receptance({{0.0, 0.09}, {0.0, -0.01}}), InputError);
}

TEST(PlateCalibration, AnalyticDerivativesMatchFiniteDifferences) {
  double worst = 0.0;
  // The full passenger tyre (6425 modes) and a perturbed, coarser one.
  PlateParameters other = passenger_plate(40, 7);
  other.tension_x = 3e4;
  other.bending_xy = 1.0;
  other.loss_factor = 0.3;
  for (const PlateParameters& p : {passenger_plate(), other}) {
    const PlateCalibration model(p);
    for (const FrfPoints& points : {FrfPoints{{0.0, 0.09}, {0.0, 0.09}}, FrfPoints{{0.1, 0.06}, {0.0, 0.09}}}) {
      const auto f = model.receptance(points);
      for (double hz : {30.0, 82.0, 250.0, 1000.0, 3000.0})
        worst = std::max(worst, log_gradient_error(*f, model.file_values(), two_pi * hz, all(8)));
    }
  }
  std::printf("  plate analytic derivatives vs central differences: max relative error %.2e\n", worst);
  // Thousands of modal terms of both signs: rounding in the sums limits the difference quotient.
  EXPECT_LT(worst, 1e-7);
}

TEST(PlateCalibration, ValidRangeFollowsTheModalTruncation) {
  // Passenger tyre: the first mode left out is (0, 26) at 16.5 kHz (By k⁴ dominates); half of it.
  const PlateCalibration full(passenger_plate());
  EXPECT_GT(full.highest_frequency_hz(), 7000.0);
  EXPECT_LT(full.highest_frequency_hz(), 9000.0);
  const PlateCalibration coarse(passenger_plate(16, 3));
  EXPECT_LT(coarse.highest_frequency_hz(), full.highest_frequency_hz());
}

TEST(GreensModelCalibration, CentralDifferencesThroughTheFactoryMatchTheSdofJets) {
  toml::table file;
  file.insert("model", "coupled_sdof");
  file.insert("mass", 1.0);
  file.insert("damping", 50.0);
  file.insert("stiffness", 500.0);
  file.insert("contact_stiffness", 1e5);
  file.insert("coupling", 0.4);
  file.insert("spacing", 0.01);
  const GreensModelCalibration generic(file, "generic.toml");
  const SdofCalibration sdof({1.0, 50.0, 500.0, 1e5}, true, 0.4, 0.01);
  EXPECT_EQ(generic.name(), "coupled_sdof");
  // Its parameters: every positive real key (coupling too, here: it is positive).
  std::vector<std::string> names;
  for (const auto& p : generic.parameters()) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"contact_stiffness", "coupling", "damping", "mass", "spacing",
                                              "stiffness"}));
  const auto g = generic.receptance({{0.01, 0}, {0, 0}});
  const auto s = sdof.receptance({{0.01, 0}, {0, 0}});
  // generic order: contact_stiffness, coupling, damping, mass, spacing, stiffness.
  const std::vector<double> gv = generic.file_values();
  const std::vector<double> sv = sdof.file_values();
  const std::size_t map[] = {3, 4, 1, 0, 99, 2};  // generic index -> sdof index (spacing: none)
  double worst = 0.0;
  for (double hz : {1.0, 10.0, 100.0}) {
    const double omega = two_pi * hz;
    std::vector<std::complex<double>> dg(6), ds(5);
    const std::complex<double> ag = g->evaluate(gv, omega, dg.data(), all(6));
    const std::complex<double> as = s->evaluate(sv, omega, ds.data(), all(5));
    EXPECT_NEAR(std::abs(ag - as), 0.0, 1e-14 * std::abs(as));
    for (std::size_t k = 0; k < 6; ++k) {
      const std::complex<double> expected = map[k] == 99 ? 0.0 : ds[map[k]];
      worst = std::max(worst, std::abs(dg[k] - expected) * gv[k] / std::abs(as));
      EXPECT_NEAR(std::abs(dg[k] - expected) * gv[k], 0.0, 1e-7 * std::abs(as)) << names[k] << " at " << hz << " Hz";
    }
  }
  std::printf("  generic central differences vs sdof Jets: max relative error %.2e\n", worst);
}

// ------------------------------------------------------------------------------------------
// two_layer

TwoLayerParameters passenger_two_layer() {
  return read_two_layer_tyre(
      CaseFile::load_model(std::string(ROLLNOISE_SOURCE_DIR) + "/models/tyres/passenger_205_55R16_two_layer.toml")
          .top());
}

TEST(TwoLayerCalibration, KeptModesAndTailEqualTheTyresOwnModalSum) {
  // A lattice four times the cell's first sinc zero (instead of 16) keeps the reference, the
  // tyre's own mode-by-mode sum over the same orders (TwoLayerResponse::receptance, 10 mm cells),
  // to about 0.6 s a frequency.
  TwoLayerParameters p = passenger_two_layer();
  const TwoLayerCalibration model(p, 500.0, 4.0);
  p.circumferential_modes = model.last_circumferential_order();
  p.lateral_modes = model.last_lateral_order();
  const TwoLayerTyre tyre(p);
  const double cell = TwoLayerCalibration::transducer_size;
  std::printf("  two_layer, band to 500 Hz: %zu kept modes + %zu tail nodes for %d x %d orders\n", model.kept_modes(),
              model.tail_nodes(), p.circumferential_modes, p.lateral_modes);
  const std::vector<FrfPoints> frfs = {{{0.0, 0.09}, {0.0, 0.09}},    // point, centre
                                       {{0.1, 0.09}, {0.0, 0.09}},    // along
                                       {{0.0, 0.045}, {0.0, 0.045}},  // point, off-centre
                                       {{0.0, 0.045}, {0.0, 0.09}}};  // across
  double worst = 0.0;
  for (double hz : {25.0, 160.0, 500.0}) {
    const auto response = tyre.response(two_pi * hz);
    for (const FrfPoints& f : frfs) {
      const std::complex<double> expected = response.receptance({f.response.x, f.response.y, cell, cell},
                                                                {f.excitation.x, f.excitation.y, cell, cell});
      const std::complex<double> got = model.receptance(f)->evaluate(model.file_values(), two_pi * hz, nullptr, {});
      const double error = std::abs(got - expected) / std::abs(expected);
      std::printf("    %5.0f Hz  (%.3f, %.3f) <- (%.3f, %.3f): |alpha| %.4e m/N, error %.2e\n", hz, f.response.x,
                  f.response.y, f.excitation.x, f.excitation.y, std::abs(expected), error);
      worst = std::max(worst, error);
    }
  }
  EXPECT_LT(worst, 1e-3);
}

TEST(TwoLayerCalibration, CentralDifferencesMatchExtrapolatedOnes) {
  // Every fittable parameter, point and transfer, in and at the top of the band; the file's
  // values and a tyre with softer, lossier rubber and a stiffer belt. Errors are rated against
  // the larger of |α| and |p·∂α/∂p|.
  TwoLayerParameters other = passenger_two_layer();
  other.tread_youngs_modulus = 2.5e6;
  other.tread_loss_factor = 0.25;
  other.belt.youngs_x = 5e9;
  other.tension_x = 4e4;
  other.foundation_loss_factor = 0.02;
  double worst = 0.0;
  for (const TwoLayerParameters& p : {passenger_two_layer(), other}) {
    const TwoLayerCalibration model(p, 400.0);
    for (const FrfPoints& points : {FrfPoints{{0.0, 0.09}, {0.0, 0.09}}, FrfPoints{{0.1, 0.06}, {0.0, 0.09}}}) {
      const auto f = model.receptance(points);
      for (double hz : {30.0, 120.0, 400.0})
        worst = std::max(worst, log_gradient_error(*f, model.file_values(), two_pi * hz,
                                                   all(model.parameters().size()), false, true));
    }
  }
  std::printf("  two_layer central differences vs extrapolated ones: max relative error %.2e\n", worst);
  // The difference quotients' own error: the layer solutions' rounding, amplified by the
  // cancelling terms of the modal sum, over the step 1e-5 (a step of 1e-6 gives 2e-5; 1e-4,
  // truncation on the centre point's resonance at 400 Hz, 3e-5). Far below what the fit needs.
  EXPECT_LT(worst, 5e-6);
}

TEST(TwoLayerCalibration, ParametersBandAndPositions) {
  const TwoLayerCalibration model(passenger_two_layer());
  EXPECT_EQ(model.name(), "two_layer");
  EXPECT_EQ(model.highest_frequency_hz(), TwoLayerCalibration::default_band_top_hz);
  EXPECT_EQ(model.default_free_parameters(),
            (std::vector<std::string>{"belt_youngs_modulus_x", "belt_youngs_modulus_y", "tension_x", "tension_y",
                                      "foundation_stiffness", "tread_youngs_modulus", "belt_loss_factor",
                                      "tread_loss_factor", "foundation_loss_factor"}));
  // Loss factors stay below what the causal modulus can carry.
  const FitParameter& eta = model.parameters()[static_cast<std::size_t>(model.index_of("tread_loss_factor"))];
  EXPECT_LT(eta.upper, 0.337);
  EXPECT_EQ(model.index_of("tread_poisson_ratio"), -1) << "Poisson's ratios are not fitted";
  // More band, more kept modes.
  EXPECT_GT(TwoLayerCalibration(passenger_two_layer(), 1000.0).kept_modes(), 2 * model.kept_modes());
  // A cell must lie on the belt; the error names the range.
  try {
    (void)model.receptance({{0.0, 0.003}, {0.0, 0.09}});
    ADD_FAILURE() << "a cell over the belt's edge";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.problem()).find("0.005 to 0.175"), std::string::npos) << e.problem();
  }
  // Values outside the physical range give no response (the fit steps back), not an exception.
  std::vector<double> values = model.file_values();
  values[static_cast<std::size_t>(model.index_of("belt_youngs_modulus_y"))] = 1e12;  // ν_yx > √(E_y/E_x)
  std::vector<std::complex<double>> gradient(values.size());
  const std::size_t wanted[] = {0};
  EXPECT_TRUE(std::isnan(model.receptance({{0.0, 0.09}, {0.0, 0.09}})->evaluate(values, 100.0, gradient.data(), wanted).real()));
}

// The whole residual: complex log of model over measured mobility, mass loading with the
// point receptance at the response, unknowns in log space, checked by Ceres' own
// finite-difference Jacobian.
double residual_check(const CalibrationModel& model, const FrfPoints& points, const std::vector<std::string>& free,
                      double mass, bool fit_mass, const std::vector<double>& frequencies) {
  FitLayout layout;
  layout.parameters = model.parameters();
  for (const auto& name : free) layout.free.push_back(static_cast<std::size_t>(model.index_of(name)));
  layout.transducer_mass = mass;
  layout.fit_transducer_mass = fit_mass;
  const auto transfer = model.receptance(points);
  const auto at_response = model.receptance({points.response, points.response});
  const bool point = points.response.x == points.excitation.x && points.response.y == points.excitation.y;
  std::mt19937_64 rng(7);
  std::vector<double> x = layout.unknowns_of(model.file_values(), mass);
  for (double& v : x) v += 0.2 * (static_cast<double>(rng() % 1000) / 1000.0 - 0.5);  // away from the file values
  double worst = 0.0;
  for (double hz : frequencies) {
    const FrfPointResidual residual(layout, *transfer, point ? nullptr : at_response.get(), hz,
                                    std::complex<double>(1e-3, -2e-4));
    ceres::NumericDiffOptions options;
    options.relative_step_size = 1e-6;
    options.ridders_relative_initial_step_size = 1e-4;  // GradientChecker uses Ridders extrapolation
    const std::vector<const ceres::Manifold*>* no_manifolds = nullptr;
    const ceres::GradientChecker checker(&residual, no_manifolds, options);
    ceres::GradientChecker::ProbeResults results;
    const double* parameters[] = {x.data()};
    checker.Probe(parameters, 1e-5, &results);
    // Ceres rates each entry by |a − b|/max(|a|, |b|), which is noise for entries that are 0
    // (a coupling's effect on a point FRF): rate them against the largest entry of their row.
    const ceres::Matrix& user = results.jacobians[0];
    const ceres::Matrix& numeric = results.numeric_jacobians[0];
    for (Eigen::Index row = 0; row < user.rows(); ++row) {
      const double scale = user.row(row).cwiseAbs().maxCoeff();
      for (Eigen::Index col = 0; col < user.cols(); ++col)
        worst = std::max(worst, std::abs(user(row, col) - numeric(row, col)) / scale);
    }
  }
  return worst;
}

TEST(FrfPointResidual, JacobianMatchesCeresGradientChecker) {
  const SdofCalibration sdof({1.0, 50.0, 500.0, 1e5}, true, 0.4, 0.01);
  const PlateCalibration plate(passenger_plate(64, 9));
  const std::vector<std::string> sdof_free = {"mass", "damping", "stiffness", "contact_stiffness", "coupling"};
  const std::vector<std::string> plate_free = {"tension_x", "bending_x", "foundation_stiffness", "loss_factor",
                                               "mass_per_area", "tension_y", "bending_y", "bending_xy"};
  double worst = 0.0;
  // Point and transfer FRFs, without and with a transducer mass, fixed and fitted.
  for (bool fit_mass : {false, true}) {
    const double mass = fit_mass ? 0.02 : 0.0;
    worst = std::max(worst, residual_check(sdof, {}, sdof_free, mass, fit_mass, {1.0, 30.0, 300.0}));
    worst = std::max(worst, residual_check(sdof, {{0.01, 0}, {0, 0}}, sdof_free, mass, fit_mass, {1.0, 30.0, 300.0}));
    worst = std::max(worst, residual_check(plate, {{0, 0.09}, {0, 0.09}}, plate_free, mass, fit_mass, {60.0, 700.0}));
    worst = std::max(worst, residual_check(plate, {{0.1, 0.06}, {0, 0.09}}, plate_free, mass, fit_mass, {60.0, 700.0}));
  }
  // A fixed, given transducer mass with parameters only.
  worst = std::max(worst, residual_check(plate, {{0.1, 0.06}, {0, 0.09}}, plate_free, 0.01, false, {120.0}));
  std::printf("  residual Jacobian vs ceres::GradientChecker: max relative error %.2e\n", worst);
  EXPECT_LT(worst, 1e-5);
}

}  // namespace
}  // namespace rollnoise
