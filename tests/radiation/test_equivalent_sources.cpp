// The equivalent-source method against classic exact results: the pulsating sphere (pressure
// and sound power), and a monopole over a rigid plane (the image-source field), with the
// error falling as sources are added. And the mirror-split solve (MirrorPairing) against the
// full one on symmetric bodies, and its fallback on bodies that are not.
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "radiation/equivalent_sources.hpp"
#include "radiation/sphere_points.hpp"

namespace rollnoise {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = std::numbers::pi;

using test::fibonacci_sphere;

const Medium kAir{};

// p(r) of a sphere of radius a pulsating with velocity v0: ρc·v0·(ika/(1 + ika))·(a/r)·e^{−ik(r−a)}.
Complex pulsating_sphere(double a, double v0, double k, double r) {
  const Complex ika(0.0, k * a);
  return kAir.density * kAir.sound_speed * v0 * ika / (1.0 + ika) * (a / r) * std::exp(Complex(0.0, -k * (r - a)));
}

Eigen::Matrix3Xd receivers_at(double r) {
  return fibonacci_sphere(9) * r;
}

TEST(EquivalentSources, PulsatingSphere) {
  const double a = 0.1;
  const double v0 = 1e-3;
  const Eigen::Matrix3Xd unit = fibonacci_sphere(400);
  const EquivalentSources model(fibonacci_sphere(120) * (0.5 * a), unit * a, unit, false, kAir);
  for (double f : {100.0, 1000.0, 3000.0}) {
    const double omega = 2 * kPi * f;
    const double k = omega / kAir.sound_speed;
    const Eigen::VectorXcd v = Eigen::VectorXcd::Constant(unit.cols(), v0);
    for (double r : {0.3, 2.0}) {
      const Eigen::VectorXcd p = model.transfer(omega, receivers_at(r)) * v;
      const Complex expected = pulsating_sphere(a, v0, k, r);
      // Discretisation (400 points, 120 sources) resolves a monopole field far better than
      // 1e-4; the regularisation adds less.
      EXPECT_LE((p.array() - expected).abs().maxCoeff(), 1e-4 * std::abs(expected)) << "f = " << f << ", r = " << r;
    }
    // Power: ½ ρc v0² 4πa² (ka)²/(1 + (ka)²); the surface sum is a 400-point quadrature.
    const double ka = k * a;
    const double power = 0.5 * kAir.density * kAir.sound_speed * v0 * v0 * 4 * kPi * a * a * ka * ka / (1 + ka * ka);
    const Eigen::VectorXd areas = Eigen::VectorXd::Constant(unit.cols(), 4 * kPi * a * a / static_cast<double>(unit.cols()));
    EXPECT_NEAR(model.sound_power(omega, Eigen::VectorXcd::Constant(unit.cols(), v0), areas), power, 1e-3 * power)
        << "f = " << f;
    // The same power from the source strengths alone, ½ qᴴSq: no surface quadrature, so only
    // the field's own error (1e-4 above) remains.
    const Eigen::VectorXcd q = model.strengths(omega, Eigen::VectorXcd::Constant(unit.cols(), v0));
    const double from_sources = 0.5 * (q.adjoint() * model.power_matrix(omega).cast<Complex>() * q)(0).real();
    EXPECT_NEAR(from_sources, power, 2e-4 * power) << "f = " << f;
  }
}

// The exact field of a monopole of volume velocity Q at s0 above a rigid plane z = 0:
// p = iωρQ·(G₀(x, s0) + G₀(x, s0')), with s0' the image.
TEST(EquivalentSources, MonopoleOverRigidPlane) {
  const Eigen::Vector3d s0(0.0, 0.0, 0.15);
  const double a = 0.1;  // a sphere around the source, clear of the plane
  const Complex q(2e-5, 1e-5);
  const Eigen::Matrix3Xd unit = fibonacci_sphere(400);
  const Eigen::Matrix3Xd surface = (unit * a).colwise() + s0;
  const EquivalentSources model((fibonacci_sphere(120) * (0.5 * a)).colwise() + s0, surface, unit, true, kAir);
  Eigen::Matrix3Xd receivers(3, 5);
  receivers << 0.5, -1.0, 0.0, 2.0, 7.5,  //
      0.0, 0.3, 1.0, -1.0, 0.0,           //
      0.01, 0.2, 0.5, 1.2, 1.2;
  for (double f : {200.0, 1000.0, 3000.0}) {
    const double omega = 2 * kPi * f;
    const double k = omega / kAir.sound_speed;
    Eigen::VectorXcd v(surface.cols());
    for (Eigen::Index m = 0; m < surface.cols(); ++m)
      v(m) = -q * unit.col(m).cast<Complex>().dot(helmholtz_green_gradient(surface.col(m), s0, k, true));
    const Eigen::VectorXcd p = model.transfer(omega, receivers) * v;
    for (Eigen::Index r = 0; r < receivers.cols(); ++r) {
      // The image term written out here, not through helmholtz_green's rigid_plane switch.
      const Eigen::Vector3d x = receivers.col(r);
      const Eigen::Vector3d image(s0.x(), s0.y(), -s0.z());
      const double r1 = (x - s0).norm();
      const double r2 = (x - image).norm();
      const Complex expected = Complex(0.0, omega * kAir.density) * q *
                               (std::exp(Complex(0.0, -k * r1)) / (4 * kPi * r1) + std::exp(Complex(0.0, -k * r2)) / (4 * kPi * r2));
      EXPECT_LE(std::abs(p(r) - expected), 1e-4 * std::abs(expected)) << "f = " << f << ", receiver " << r;
    }
  }
}

// A monopole of volume velocity Q at height h over a rigid plane radiates
// W = W₀·(1 + sin(2kh)/(2kh)) into the half-space, W₀ = ρck²|Q|²/(8π) its free-field power
// (the image's interference; e.g. Pierce, Acoustics, §5.5).
TEST(EquivalentSources, PowerOfAMonopoleOverARigidPlane) {
  for (double h : {0.05, 0.3}) {
    Eigen::Matrix3Xd source(3, 1);
    source << 0.1, -0.2, h;
    const Eigen::Matrix3Xd surface = (fibonacci_sphere(8) * (0.5 * h)).colwise() + source.col(0);
    const EquivalentSources model(source, surface, fibonacci_sphere(8), true, kAir);
    const Complex q(3e-5, -1e-5);
    for (double f : {50.0, 500.0, 3000.0}) {
      const double omega = 2 * kPi * f;
      const double k = omega / kAir.sound_speed;
      const double w0 = kAir.density * kAir.sound_speed * k * k * std::norm(q) / (8 * kPi);
      const double expected = w0 * (1.0 + std::sin(2 * k * h) / (2 * k * h));
      const double w = 0.5 * std::norm(q) * model.power_matrix(omega)(0, 0).real();
      EXPECT_NEAR(w, expected, 1e-12 * expected) << "h = " << h << ", f = " << f;
    }
  }
}

// A mirror-symmetric (y → −y) sphere of radius a at `centre` (on the plane y = 0): the Fibonacci
// points with y > 0, their mirror images, and `on_plane` points on the great circle y = 0 (which
// the mirror maps to themselves). Unit outward normals in `normals`.
Eigen::Matrix3Xd symmetric_sphere(int n, int on_plane, double a, const Eigen::Vector3d& centre,
                                  Eigen::Matrix3Xd* normals = nullptr) {
  const Eigen::Matrix3Xd f = fibonacci_sphere(n);
  std::vector<Eigen::Vector3d> unit;
  for (Eigen::Index i = 0; i < f.cols(); ++i)
    if (f(1, i) > 1e-3) {
      unit.push_back(f.col(i));
      unit.emplace_back(f(0, i), -f(1, i), f(2, i));
    }
  for (int i = 0; i < on_plane; ++i) {
    const double t = 2 * kPi * (i + 0.25) / on_plane;
    unit.emplace_back(std::cos(t), 0.0, std::sin(t));
  }
  Eigen::Matrix3Xd p(3, static_cast<Eigen::Index>(unit.size()));
  for (std::size_t i = 0; i < unit.size(); ++i) p.col(static_cast<Eigen::Index>(i)) = unit[i];
  if (normals) *normals = p;
  return (p * a).colwise() + centre;
}

// For the recorded errors (std::to_string's fixed format shows them as 0).
std::string scientific(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", x);
  return text;
}

double relative_difference(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

// The split solve is the full one (to rounding) for velocities with no symmetry: both halves
// and their recombination, the √2 of the orthonormal combinations and the points and sources on
// the plane, in the free field and over the rigid plane.
TEST(EquivalentSources, MirrorSplitSolveEqualsTheFullSolve) {
  const double a = 0.1;
  for (bool rigid_plane : {false, true}) {
    const Eigen::Vector3d centre(0.02, 0.0, rigid_plane ? 0.15 : 0.0);
    for (int on_plane : {0, 6}) {
      Eigen::Matrix3Xd normals;
      const Eigen::Matrix3Xd surface = symmetric_sphere(400, 2 * on_plane, a, centre, &normals);
      const Eigen::Matrix3Xd sources = symmetric_sphere(120, on_plane, 0.5 * a, centre);
      // Both by the QR (least_squares.hpp): the split's algebra to rounding. (By the normal
      // equations, κ(VᴴV) ≈ 2e7 for this sphere with its sources half way in, the two agreed
      // to 9e-9 in the transfer and 2e-7 in the strengths: that much is the normal equations'.)
      EquivalentSources split(sources, surface, normals, rigid_plane, kAir);
      EquivalentSources full(sources, surface, normals, rigid_plane, kAir, EquivalentSources::Symmetry::none);
      split.set_least_squares_method(LeastSquaresMethod::qr);
      full.set_least_squares_method(LeastSquaresMethod::qr);
      ASSERT_TRUE(split.mirror_symmetric());
      ASSERT_FALSE(full.mirror_symmetric());
      Eigen::Matrix3Xd receivers(3, 4);
      receivers << 0.5, -1.0, 0.0, 2.0,  //
          0.1, 0.3, -1.0, 0.0,           //
          0.2, 0.4, 0.5, 1.2;
      std::srand(7);
      const Eigen::MatrixXcd v = Eigen::MatrixXcd::Random(surface.cols(), 3);  // no symmetry
      for (double f : {300.0, 3000.0}) {
        const double omega = 2 * kPi * f;
        const EquivalentSourceSolve s = split.solve(omega), r = full.solve(omega);
        EXPECT_TRUE(s.mirror_split());
        const double transfer_error = relative_difference(split.transfer(omega, receivers), full.transfer(omega, receivers));
        const double strength_error = relative_difference(s.strengths(v), r.strengths(v));
        EXPECT_LE(transfer_error, 1e-9) << "f = " << f << ", plane " << rigid_plane << ", on the plane " << on_plane;
        EXPECT_LE(strength_error, 1e-9) << "f = " << f << ", plane " << rigid_plane << ", on the plane " << on_plane;
        EXPECT_LE(std::abs(split.sound_power(omega, v.col(0), Eigen::VectorXd::Ones(v.rows())) -
                           full.sound_power(omega, v.col(0), Eigen::VectorXd::Ones(v.rows()))),
                  1e-9 * std::abs(full.sound_power(omega, v.col(0), Eigen::VectorXd::Ones(v.rows()))));
        std::string key = "split_error_";
        key += std::to_string(static_cast<int>(f));
        key += rigid_plane ? "Hz_plane_" : "Hz_free_";
        key += std::to_string(on_plane);
        RecordProperty(key + "_transfer", scientific(transfer_error));
        RecordProperty(key + "_strengths", scientific(strength_error));
      }
    }
  }
}

// Sets that are not mirror-symmetric take the full solve: the Fibonacci lattice, a symmetric
// set with one point moved by 2e-7 m (1e-6 of its size), mirrored points whose normals are not mirrored,
// and symmetric points with sources that are not.
TEST(EquivalentSources, UnpairedSetsFallBackToTheFullSolve) {
  const double a = 0.1;
  const Eigen::Vector3d centre(0.0, 0.0, 0.15);
  Eigen::Matrix3Xd normals;
  const Eigen::Matrix3Xd surface = symmetric_sphere(200, 0, a, centre, &normals);
  const Eigen::Matrix3Xd sources = symmetric_sphere(60, 0, 0.5 * a, centre);
  EXPECT_TRUE(EquivalentSources(sources, surface, normals, true, kAir).mirror_symmetric());

  const Eigen::Matrix3Xd lattice = fibonacci_sphere(200);
  EXPECT_FALSE(EquivalentSources((fibonacci_sphere(60) * 0.5 * a).colwise() + centre, (lattice * a).colwise() + centre,
                                 lattice, true, kAir)
                   .mirror_symmetric());
  Eigen::Matrix3Xd moved = surface;
  moved(0, 5) += 2e-7;
  EXPECT_FALSE(EquivalentSources(sources, moved, normals, true, kAir).mirror_symmetric());
  Eigen::Matrix3Xd turned = normals;
  turned.col(3) = Eigen::Vector3d(turned(0, 3), turned(2, 3), turned(1, 3)).normalized();
  EXPECT_FALSE(EquivalentSources(sources, surface, turned, true, kAir).mirror_symmetric());
  Eigen::Matrix3Xd unpaired_sources = sources;
  unpaired_sources(1, 0) *= 0.5;
  const EquivalentSources fallback(unpaired_sources, surface, normals, true, kAir);
  EXPECT_FALSE(fallback.mirror_symmetric());
  // The fallback is the full solve: the same as asking for it.
  const double omega = 2 * kPi * 1000.0;
  EXPECT_FALSE(fallback.solve(omega).mirror_split());
  const EquivalentSources full(unpaired_sources, surface, normals, true, kAir, EquivalentSources::Symmetry::none);
  Eigen::Matrix3Xd receiver(3, 1);
  receiver << 0.5, 0.2, 0.1;
  EXPECT_EQ(relative_difference(fallback.transfer(omega, receiver), full.transfer(omega, receiver)), 0.0);
}

TEST(EquivalentSources, MirrorPairingOfPointsOnAndOffThePlane) {
  Eigen::Matrix3Xd p(3, 5);
  p << 1.0, 2.0, 1.0, 3.0, 2.0,  //
      0.5, 0.0, -0.5, 0.0, 0.0,  //
      1.0, 1.0, 1.0, 1.0, 2.0;
  const auto pairing = find_mirror_pairing(p, Eigen::Matrix3Xd(3, 0), 1e-12);
  ASSERT_TRUE(pairing.has_value());
  ASSERT_EQ(pairing->pairs.size(), 1u);
  EXPECT_EQ(pairing->pairs[0], std::make_pair(Eigen::Index{0}, Eigen::Index{2}));  // y > 0 first
  EXPECT_EQ(pairing->fixed, (std::vector<Eigen::Index>{1, 3, 4}));
  // The bases are orthonormal: combine inverts even/odd and norms are kept.
  std::srand(3);
  const Eigen::MatrixXcd x = Eigen::MatrixXcd::Random(5, 2);
  const Eigen::MatrixXcd e = pairing->even(x), o = pairing->odd(x);
  EXPECT_NEAR(e.squaredNorm() + o.squaredNorm(), x.squaredNorm(), 1e-14);
  EXPECT_LE((pairing->combine(e, o) - x).cwiseAbs().maxCoeff(), 1e-15);
  // Two points at one mirror position: no one-to-one pairing.
  Eigen::Matrix3Xd doubled(3, 3);
  doubled << 1.0, 1.0, 1.0,  //
      0.5, -0.5, -0.5,       //
      1.0, 1.0, 1.0;
  EXPECT_FALSE(find_mirror_pairing(doubled, Eigen::Matrix3Xd(3, 0), 1e-12).has_value());
}

TEST(EquivalentSources, ErrorFallsWithMoreSources) {
  // A sphere vibrating in a dipole pattern v = v0·cosθ at ka = 3.7: its exterior field needs more
  // than a monopole, and the error must fall as sources are added.
  const double a = 0.1;
  const double f = 2000.0;
  const double omega = 2 * kPi * f;
  const double k = omega / kAir.sound_speed;
  const Eigen::Matrix3Xd unit = fibonacci_sphere(600);
  Eigen::VectorXcd v(unit.cols());
  for (Eigen::Index m = 0; m < unit.cols(); ++m) v(m) = 1e-3 * unit(2, m);
  // Exact: p = A·h₁(kr)·cosθ with h₁ the spherical Hankel function of the second kind (e^{iωt}),
  // h₁(x) = e^{−ix}(i/x² − 1/x)… here via p(r)/p(a) ratio: only the shape matters, so compare
  // p at 2a along the axis against the analytic ratio h₁(2ka)/h₁'(ka) scaling.
  const auto h1 = [](double x) { return std::exp(Complex(0.0, -x)) * (Complex(0.0, 1.0) / (x * x) - 1.0 / x); };
  const auto dh1 = [&](double x) {
    const double e = 1e-6 * x;
    return (h1(x + e) - h1(x - e)) / (2 * e);
  };
  // v_r = −p_r/(iωρ): p(r, θ) = −iωρ v0 cosθ h₁(kr)/(k h₁'(ka)).
  const double r = 0.3;
  Eigen::Matrix3Xd receiver(3, 1);
  receiver << 0.0, 0.0, r;
  const Complex expected = Complex(0.0, -omega * kAir.density) * 1e-3 * h1(k * r) / (k * dh1(k * a));
  double previous = 1e300;
  for (int sources : {4, 16, 64, 200}) {
    const EquivalentSources model(fibonacci_sphere(sources) * (0.5 * a), unit * a, unit, false, kAir);
    const double error = std::abs((model.transfer(omega, receiver) * v)(0) - expected) / std::abs(expected);
    EXPECT_LT(error, previous) << sources << " sources";
    previous = error;
    RecordProperty("error_" + std::to_string(sources) + "_sources", std::to_string(error));
  }
  EXPECT_LT(previous, 1e-3);
}

// A sphere of radius a at `centre` (on the planes x = 0 and y = 0) symmetric under both mirrors
// x → −x and y → −y: Fibonacci points of one quadrant and their three images, `on_planes`
// points on each of the two great circles in the planes (mapped to themselves by one mirror),
// and the two poles on the z axis (by both). Unit outward normals in `normals`.
Eigen::Matrix3Xd doubly_symmetric_sphere(int n, int on_planes, double a, const Eigen::Vector3d& centre,
                                         Eigen::Matrix3Xd* normals = nullptr) {
  const Eigen::Matrix3Xd f = fibonacci_sphere(n);
  std::vector<Eigen::Vector3d> unit;
  for (Eigen::Index i = 0; i < f.cols(); ++i)
    if (f(0, i) > 1e-3 && f(1, i) > 1e-3)
      for (double sx : {1.0, -1.0})
        for (double sy : {1.0, -1.0}) unit.emplace_back(sx * f(0, i), sy * f(1, i), f(2, i));
  for (int i = 0; i < on_planes; ++i) {
    const double t = kPi * (i + 0.5) / on_planes - 0.5 * kPi;  // (−π/2, π/2): x > 0, then mirrored
    for (double sx : {1.0, -1.0}) unit.emplace_back(sx * std::cos(t), 0.0, std::sin(t));
    for (double sy : {1.0, -1.0}) unit.emplace_back(0.0, sy * std::cos(t), std::sin(t));
  }
  unit.emplace_back(0.0, 0.0, 1.0);
  unit.emplace_back(0.0, 0.0, -1.0);
  Eigen::Matrix3Xd p(3, static_cast<Eigen::Index>(unit.size()));
  for (std::size_t i = 0; i < unit.size(); ++i) p.col(static_cast<Eigen::Index>(i)) = unit[i];
  if (normals) *normals = p;
  return (p * a).colwise() + centre;
}

// Both mirrors (symmetry_basis.hpp): four blocks, the full solve to rounding, for monopoles and
// for combined sources (whose normals must mirror too), free and over the rigid plane.
TEST(EquivalentSources, SplitByBothMirrorsEqualsTheFullSolve) {
  const double a = 0.1;
  for (bool rigid_plane : {false, true})
    for (bool combined : {false, true}) {
      const Eigen::Vector3d centre(0.0, 0.0, rigid_plane ? 0.15 : 0.0);
      Eigen::Matrix3Xd normals, source_normals;
      const Eigen::Matrix3Xd surface = doubly_symmetric_sphere(400, 5, a, centre, &normals);
      const Eigen::Matrix3Xd sources = doubly_symmetric_sphere(140, 2, 0.5 * a, centre, &source_normals);
      std::optional<CombinedSources> layer;
      if (combined) layer = CombinedSources{source_normals, 1.0, 50.0};
      EquivalentSources split(sources, surface, normals, rigid_plane, kAir, EquivalentSources::Symmetry::automatic, layer);
      EquivalentSources one_mirror(sources, surface, normals, rigid_plane, kAir, EquivalentSources::Symmetry::centre_plane, layer);
      EquivalentSources full(sources, surface, normals, rigid_plane, kAir, EquivalentSources::Symmetry::none, layer);
      for (EquivalentSources* model : {&split, &one_mirror, &full}) model->set_least_squares_method(LeastSquaresMethod::qr);
      ASSERT_EQ(split.symmetry_blocks(), 4);
      ASSERT_EQ(one_mirror.symmetry_blocks(), 2);
      ASSERT_EQ(full.symmetry_blocks(), 1);
      Eigen::Matrix3Xd receivers(3, 4);
      receivers << 0.5, -1.0, 0.1, 2.0,  //
          0.1, 0.3, -1.0, 0.0,           //
          0.2, 0.4, 0.5, 1.2;
      std::srand(5);
      const Eigen::MatrixXcd v = Eigen::MatrixXcd::Random(surface.cols(), 3);  // no symmetry
      for (double f : {300.0, 3000.0}) {
        const double omega = 2 * kPi * f;
        const EquivalentSourceSolve s = split.solve(omega), m = one_mirror.solve(omega), r = full.solve(omega);
        EXPECT_EQ(s.blocks(), 4);
        const Eigen::MatrixXcd pressures = full.pressure_matrix(omega, receivers);
        const double transfer_error = relative_difference(s.transfer(pressures), r.transfer(pressures));
        const double mirror_error = relative_difference(m.transfer(pressures), r.transfer(pressures));
        const double strength_error = relative_difference(s.strengths(v), r.strengths(v));
        // The power of any strengths by the blocks of S, against the full S.
        const Eigen::MatrixXcd q = Eigen::MatrixXcd::Random(sources.cols(), 2);
        const Eigen::VectorXd power = split.radiated_power(omega, q), reference = full.radiated_power(omega, q);
        const double power_error = (power - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
        const std::string where = "f = " + std::to_string(f) + ", plane " + std::to_string(rigid_plane) + ", combined " +
                                  std::to_string(combined);
        EXPECT_LE(transfer_error, 1e-9) << where;
        EXPECT_LE(mirror_error, 1e-9) << where;
        EXPECT_LE(strength_error, 1e-8) << where;
        EXPECT_LE(power_error, 1e-12) << where;
        RecordProperty("split4_error_" + std::to_string(static_cast<int>(f)) + (rigid_plane ? "_plane" : "_free") +
                           (combined ? "_combined" : "_monopoles"),
                       scientific(transfer_error));
      }
    }
}

// Combined sources (Ψ = ∂G/∂n_s + i(k + η₀)G, equivalent_sources.hpp) on the pulsating sphere:
// the exact pressure, and the power ½qᴴSq from their far fields, at ka = 0.18 … 5.5.
TEST(EquivalentSources, CombinedSourcesPulsatingSphere) {
  const double a = 0.1, v0 = 1e-3;
  const Eigen::Matrix3Xd unit = fibonacci_sphere(400);
  const Eigen::Matrix3Xd inner = fibonacci_sphere(120);
  const EquivalentSources model(inner * (0.5 * a), unit * a, unit, false, kAir, EquivalentSources::Symmetry::automatic,
                                CombinedSources{inner, 1.0, 50.0});
  ASSERT_TRUE(model.combined_sources());
  for (double f : {100.0, 1000.0, 3000.0}) {
    const double omega = 2 * kPi * f, k = omega / kAir.sound_speed;
    const Eigen::VectorXcd v = Eigen::VectorXcd::Constant(unit.cols(), v0);
    for (double r : {0.3, 2.0}) {
      const Eigen::VectorXcd p = model.transfer(omega, receivers_at(r)) * v;
      const Complex expected = pulsating_sphere(a, v0, k, r);
      EXPECT_LE((p.array() - expected).abs().maxCoeff(), 1e-4 * std::abs(expected)) << "f = " << f << ", r = " << r;
    }
    const double ka = k * a;
    const double power = 0.5 * kAir.density * kAir.sound_speed * v0 * v0 * 4 * kPi * a * a * ka * ka / (1 + ka * ka);
    const Eigen::VectorXcd q = model.strengths(omega, Eigen::VectorXcd::Constant(unit.cols(), v0));
    EXPECT_NEAR(model.radiated_power(omega, q)(0), power, 2e-4 * power) << "f = " << f;
    // S is Hermitian.
    const Eigen::MatrixXcd s = model.power_matrix(omega);
    EXPECT_LE((s - s.adjoint()).cwiseAbs().maxCoeff(), 1e-12 * s.cwiseAbs().maxCoeff());
  }
}

// The power matrix of combined sources over the rigid plane against the power their pressure
// carries through a large hemisphere (Gauss–Legendre in cos θ, uniform in φ; R = 500 m, where
// the sources' extent of 0.3 m makes the far field exact to ~1e-3).
TEST(EquivalentSources, CombinedSourcesPowerIsTheFarFieldsPower) {
  Eigen::Matrix3Xd sources(3, 3), normals(3, 3), surface(3, 3);
  sources << 0.0, 0.1, -0.05,  //
      0.02, -0.04, 0.0,        //
      0.05, 0.12, 0.3;
  normals << 0.0, 0.6, -0.48,  //
      0.0, 0.0, 0.6,           //
      -1.0, 0.8, 0.64;
  surface = sources;  // unused here but for the model's checks
  surface.row(2).array() += 0.01;
  const EquivalentSources model(sources, surface, normals, true, kAir, EquivalentSources::Symmetry::none,
                                CombinedSources{normals, 1.0, 50.0});
  const Eigen::VectorXcd q = (Eigen::VectorXcd(3) << Complex(1e-4, 0.0), Complex(-2e-5, 7e-5), Complex(3e-5, 3e-5)).finished();
  const int nodes = 48, around = 96;
  // Gauss–Legendre nodes on [0, 1] for cos θ (the upper half-space).
  std::vector<double> x(nodes), w(nodes);
  for (int i = 0; i < nodes; ++i) {
    double t = std::cos(kPi * (i + 0.75) / (nodes + 0.5));
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;
      for (int n = 2; n <= nodes; ++n) {
        const double p2 = ((2.0 * n - 1.0) * t * p1 - (n - 1.0) * p0) / n;
        p0 = p1;
        p1 = p2;
      }
      const double dp = nodes * (t * p1 - p0) / (t * t - 1.0);
      t -= p1 / dp;
      if (it > 5 && std::abs(p1 / dp) < 1e-15) {
        x[static_cast<std::size_t>(i)] = 0.5 * (t + 1.0);
        w[static_cast<std::size_t>(i)] = 1.0 / ((1.0 - t * t) * dp * dp);  // = ½·2/((1−t²)P′²)
        break;
      }
    }
  }
  const double radius = 500.0;
  for (double f : {200.0, 2000.0, 5000.0}) {
    const double omega = 2 * kPi * f;
    Eigen::Matrix3Xd sphere(3, nodes * around);
    Eigen::VectorXd weight(nodes * around);
    for (int i = 0; i < nodes; ++i)
      for (int j = 0; j < around; ++j) {
        const double c = x[static_cast<std::size_t>(i)], s = std::sqrt(1.0 - c * c), phi = 2 * kPi * (j + 0.5) / around;
        sphere.col(i * around + j) << radius * s * std::cos(phi), radius * s * std::sin(phi), radius * c;
        weight(i * around + j) = w[static_cast<std::size_t>(i)] * 2 * kPi / around * radius * radius;
      }
    const Eigen::VectorXcd p = model.pressure_matrix(omega, sphere) * q;
    const double far = (p.cwiseAbs2().array() * weight.array()).sum() / (2.0 * kAir.density * kAir.sound_speed);
    const double power = model.radiated_power(omega, q)(0);
    EXPECT_NEAR(power, far, 2e-3 * far) << "f = " << f;
    RecordProperty("combined_power_vs_far_field_" + std::to_string(static_cast<int>(f)) + "Hz", scientific(power / far - 1.0));
  }
}

// Collocation weights (EquivalentSources::set_collocation_weights): equal weights change nothing
// but rounding; the weighted fit is the unweighted fit of the scaled rows; the split solve keeps
// them, and weights that differ at mirror partners are refused.
TEST(EquivalentSources, CollocationWeights) {
  const double a = 0.1;
  const Eigen::Vector3d centre(0.02, 0.0, 0.15);
  Eigen::Matrix3Xd normals;
  const Eigen::Matrix3Xd surface = symmetric_sphere(300, 6, a, centre, &normals);
  const Eigen::Matrix3Xd sources = symmetric_sphere(90, 3, 0.5 * a, centre);
  EquivalentSources model(sources, surface, normals, true, kAir);
  model.set_least_squares_method(LeastSquaresMethod::qr);
  Eigen::Matrix3Xd receivers(3, 2);
  receivers << 0.5, -1.0, 0.1, 0.3, 0.2, 0.4;
  const double omega = 2 * kPi * 1500.0;
  const Eigen::MatrixXcd plain = model.transfer(omega, receivers);
  model.set_collocation_weights(Eigen::VectorXd::Constant(surface.cols(), 7.0));
  EXPECT_LE(relative_difference(model.transfer(omega, receivers), plain), 1e-10);
  // Weights symmetric under the mirror (a function of |y|): the split and the full weighted
  // solves agree.
  Eigen::VectorXd weights(surface.cols());
  for (Eigen::Index m = 0; m < weights.size(); ++m) weights(m) = 1.0 + 4.0 * std::abs(surface(1, m) / a);
  model.set_collocation_weights(weights);
  EquivalentSources full(sources, surface, normals, true, kAir, EquivalentSources::Symmetry::none);
  full.set_least_squares_method(LeastSquaresMethod::qr);
  full.set_collocation_weights(weights);
  const Eigen::MatrixXcd weighted = model.transfer(omega, receivers);
  EXPECT_LE(relative_difference(weighted, full.transfer(omega, receivers)), 1e-9);
  EXPECT_GT(relative_difference(weighted, plain), 1e-6);  // and the weights do change the fit
  Eigen::VectorXd lopsided = weights;
  lopsided(0) *= 2.0;
  EXPECT_THROW(model.set_collocation_weights(lopsided), std::invalid_argument);
  EXPECT_THROW(model.set_collocation_weights(-weights), std::invalid_argument);
}

}  // namespace
}  // namespace rollnoise
