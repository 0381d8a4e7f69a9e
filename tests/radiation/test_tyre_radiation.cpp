// The equivalent sources on the tyre's geometry: the mesh must resolve the field. An exterior
// field known exactly, that of a monopole inside the tyre over the rigid road, is reproduced at
// the CPX and SPB receivers from its normal velocity on the tyre's surface alone. The mesh is
// mirror-symmetric about the centre plane, sources included, and the split solve this allows
// is the full one.
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "radiation/equivalent_sources.hpp"
#include "radiation/tyre_radiation.hpp"
#include "radiation/tyre_surface_mesh.hpp"

namespace rollnoise {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = std::numbers::pi;

Complex monopole_over_road(const Eigen::Vector3d& x, const Eigen::Vector3d& s, double omega, Complex q) {
  const Medium air;
  return Complex(0.0, omega * air.density) * q * helmholtz_green(x, s, omega / air.sound_speed, true);
}

TEST(TyreRadiation, MeshReproducesAKnownExteriorField) {
  const TyreSurfaceMesh mesh = make_tyre_surface_mesh({});
  const EquivalentSources model(mesh.sources, mesh.points, mesh.normals, true);
  const Eigen::Vector3d inside(0.05, 0.02, 0.3);  // in the tyre, off-centre
  Eigen::Matrix3Xd receivers(3, 4);
  receivers << 0.2, -0.2, 0.0, 0.6,  // CPX front and rear, SPB direction, ahead
      0.29, 0.29, 7.5, 0.0,          //
      0.1, 0.1, 1.2, 0.05;
  for (double f : {1000.0, 3000.0}) {
    const double omega = 2 * kPi * f;
    const double k = omega / Medium{}.sound_speed;
    Eigen::VectorXcd v(mesh.points.cols());
    for (Eigen::Index m = 0; m < v.size(); ++m)
      v(m) = -mesh.normals.col(m).cast<Complex>().dot(helmholtz_green_gradient(mesh.points.col(m), inside, k, true));
    const Eigen::VectorXcd p = model.transfer(omega, receivers) * v;
    for (Eigen::Index r = 0; r < receivers.cols(); ++r) {
      const Complex expected = monopole_over_road(receivers.col(r), inside, omega, 1.0);
      // About 5 collocation points per wavelength at 3 kHz: a few per cent is what the mesh
      // resolves there (measured 0.06–0.18 % at 1 kHz, 0.5–4.4 % at 3 kHz).
      EXPECT_LE(std::abs(p(r) - expected), (f < 2000.0 ? 0.005 : 0.05) * std::abs(expected))
          << "f = " << f << ", receiver " << r;
      RecordProperty("error_" + std::to_string(static_cast<int>(f)) + "Hz_r" + std::to_string(r),
                     std::to_string(std::abs(p(r) - expected) / std::abs(expected)));
    }
  }
}

// Issue 10 §3: the band up to 5 kHz on the undeformed graded tyre (96 around, 16 across, 12
// sidewall rings, 2 mm cells at the contact; 2948 points), on the meshes and with the sources
// the radiation stage takes (tyre_radiation.hpp: this one to 4.15 kHz, the tread split in 2 with
// 21 rings above; monopoles to 3 kHz, combined sources above). The exterior field of a monopole inside the tread near the
// contact, where the belt moves most and the horn is, and of two far from it, at the CPX and SPB
// receivers (205/55 R16: 0.18 m wide), with the velocity taken at the collocation points.
// Asserted within the 6 % at 3 kHz, 5 kHz and 5623 Hz, the 5 kHz band's upper edge, for
// the sources near the contact (measured 1.0–3.6 %); the two far from it recorded (0.2–3.0 %, but
// 7.2 % at SPB at 3 kHz, 75 Hz from where the source's image cancels its direct sound there and
// the exact pressure is small). Before issue 10 §3 this mesh with monopoles gave 1.1–6.1 % at
// 5 kHz and 3.3–18.6 % at 5623 Hz near the contact, up to 25–30 % for the far sources.
TEST(TyreRadiation, GradedMeshFieldsTo5623Hz) {
  TyreRadiationSettings settings;
  settings.mesh.around = 96;
  settings.mesh.across = 16;
  settings.mesh.sidewall_rings = 12;
  settings.mesh.contact_refinement = 10.0;
  settings.max_frequency_hz = 5623.4;
  const std::vector<RadiationMeshLevel> levels = radiation_mesh_levels(settings);
  ASSERT_EQ(levels.size(), 2u);
  const double beside = 0.5 * settings.mesh.width + 0.2;
  Eigen::Matrix3Xd receivers(3, 3);
  receivers << 0.2, -0.2, 0.0,  // cpx_front, cpx_rear, spb
      beside, beside, 7.5,      //
      0.1, 0.1, 1.2;
  struct Source {
    const char* name;
    Eigen::Vector3d position;
    bool asserted;
  };
  const Source sources[] = {{"near_contact", {0.03, 0.0, 0.012}, true},
                            {"near_contact_off_centre", {-0.02, 0.05, 0.015}, true},
                            {"near_axle", {0.05, 0.02, 0.3}, false},
                            {"tread_ahead", {0.248, 0.03, 0.175}, false}};
  for (double f : {3000.0, 5000.0, 5623.4}) {
    const TyreSurfaceMeshSpec& spec = levels[f > levels[0].top_hz ? 1 : 0].spec;
    const TyreSurfaceMesh mesh = make_tyre_surface_mesh(spec);
    const EquivalentSources model = make_tyre_model(mesh, Medium{}, f > kCombinedSourcesAboveHz);
    const double omega = 2 * kPi * f;
    const double k = omega / Medium{}.sound_speed;
    const Eigen::MatrixXcd transfer = model.transfer(omega, receivers);
    for (const Source& source : sources) {
      Eigen::VectorXcd v(mesh.points.cols());
      for (Eigen::Index m = 0; m < v.size(); ++m)
        v(m) = -mesh.normals.col(m).cast<Complex>().dot(helmholtz_green_gradient(mesh.points.col(m), source.position, k, true));
      const Eigen::VectorXcd p = transfer * v;
      for (Eigen::Index r = 0; r < receivers.cols(); ++r) {
        const Complex expected = monopole_over_road(receivers.col(r), source.position, omega, 1.0);
        const double error = std::abs(p(r) - expected) / std::abs(expected);
        if (source.asserted) {
          EXPECT_LE(error, 0.06) << source.name << ", f = " << f << ", receiver " << r;
        }
        RecordProperty(std::string(source.name) + "_" + std::to_string(static_cast<int>(f)) + "Hz_r" + std::to_string(r),
                       std::to_string(error));
        std::printf("%s, %.0f Hz, receiver %ld: %.4f\n", source.name, f, static_cast<long>(r), error);
      }
    }
  }
}

// For the recorded errors (std::to_string's fixed format shows them as 0).
std::string scientific(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", x);
  return text;
}

TEST(TyreRadiation, MeshIsMirrorSymmetricSourcesIncluded) {
  struct Case {
    const char* name;
    TyreSurfaceMeshSpec spec;
  };
  std::vector<Case> cases(10);
  cases[0].name = "default";
  cases[1].name = "graded, 16 across";
  cases[1].spec.contact_refinement = 10.0;
  cases[1].spec.across = 16;
  cases[2].name = "7 across";
  cases[2].spec.across = 7;
  cases[3].name = "graded, 5 across, 5 rings";
  cases[3].spec.contact_refinement = 4.0;
  cases[3].spec.across = 5;
  cases[3].spec.sidewall_rings = 5;
  cases[4].name = "97 around, 3 across";  // Na odd: the stride-th points in global order were not paired
  cases[4].spec.around = 97;
  cases[4].spec.across = 3;
  cases[5].name = "stride 3, 1 across";
  cases[5].spec.source_stride = 3;
  cases[5].spec.across = 1;
  cases[6].name = "stride 3, 10 across, 7 rings";
  cases[6].spec.source_stride = 3;
  cases[6].spec.across = 10;
  cases[6].spec.sidewall_rings = 7;
  cases[7].name = "33 around, 9 rings";  // sidewalls with an odd number of points
  cases[7].spec.around = 33;
  cases[7].spec.sidewall_rings = 9;
  cases[8].name = "deformed, graded, 16 across";  // the runs' base mesh
  cases[8].spec.geometry = TyreGeometry::deformed;
  cases[8].spec.contact_refinement = 10.0;
  cases[8].spec.across = 16;
  cases[9].name = "deformed, graded, tread split in 2, 21 rings";  // the runs' mesh above 4.1 kHz
  cases[9].spec = cases[8].spec;
  cases[9].spec.tread_split = 2;
  cases[9].spec.sidewall_rings = 21;
  for (const Case& c : cases) {
    const TyreSurfaceMesh mesh = make_tyre_surface_mesh(c.spec);
    const double tolerance = 1e-10 * (mesh.points.rowwise().maxCoeff() - mesh.points.rowwise().minCoeff()).norm();
    const auto points = find_mirror_pairing(mesh.points, mesh.normals, tolerance);
    const auto sources = find_mirror_pairing(mesh.sources, Eigen::Matrix3Xd(3, 0), tolerance);
    ASSERT_TRUE(points.has_value()) << c.name;
    ASSERT_TRUE(sources.has_value()) << c.name;
    // An odd count across puts one tread row on the plane, mapped to itself.
    EXPECT_EQ(static_cast<int>(points->fixed.size()), c.spec.across % 2 == 1 ? mesh.tread_around : 0) << c.name;
    // About one source per stride points: within one per tread row and two per sidewall ring
    // (the x-mirror pairs are chosen together, so a row or ring can gain or lose one).
    EXPECT_NEAR(static_cast<double>(mesh.sources.cols()), static_cast<double>(mesh.points.cols()) / c.spec.source_stride,
                static_cast<double>(c.spec.across + 2 + 2 * c.spec.sidewall_rings)) << c.name;
    EXPECT_TRUE(EquivalentSources(mesh.sources, mesh.points, mesh.normals, true).mirror_symmetric()) << c.name;
    // And under x → −x (the plane through the axle across the road), sources and their normals
    // included: the solve splits into four (symmetry_basis.hpp).
    const auto across_road = reflection_partners(mesh.points, mesh.normals, 0, tolerance);
    ASSERT_TRUE(across_road.has_value()) << c.name;
    ASSERT_TRUE(reflection_partners(mesh.sources, mesh.source_normals, 0, tolerance).has_value()) << c.name;
    EXPECT_EQ(EquivalentSources(mesh.sources, mesh.points, mesh.normals, true).symmetry_blocks(), 4) << c.name;
    EXPECT_EQ(make_tyre_model(mesh, Medium{}, true).symmetry_blocks(), 4) << c.name;
  }
}

// The split solve against the full one on the default mesh (1924 points, 962 sources) at 1 kHz:
// a velocity pattern with no symmetry, and the transfer to receivers off the centre plane.
TEST(TyreRadiation, MirrorSplitSolveEqualsTheFullSolveOnTheDefaultMesh) {
  const TyreSurfaceMesh mesh = make_tyre_surface_mesh({});
  const EquivalentSources split(mesh.sources, mesh.points, mesh.normals, true);
  const EquivalentSources full(mesh.sources, mesh.points, mesh.normals, true, Medium{}, EquivalentSources::Symmetry::none);
  ASSERT_TRUE(split.mirror_symmetric());
  Eigen::Matrix3Xd receivers(3, 3);
  receivers << 0.2, -0.2, 0.0,  //
      0.29, 0.29, 7.5,          //
      0.1, 0.1, 1.2;
  const double omega = 2 * kPi * 1000.0;
  const EquivalentSourceSolve s = split.solve(omega), f = full.solve(omega);
  const Eigen::MatrixXcd pressures = split.pressure_matrix(omega, receivers);
  const Eigen::MatrixXcd ts = s.transfer(pressures), tf = f.transfer(pressures);
  std::srand(11);
  const Eigen::MatrixXcd v = Eigen::MatrixXcd::Random(mesh.points.cols(), 2);
  const Eigen::MatrixXcd qs = s.strengths(v), qf = f.strengths(v);
  const double transfer_error = (ts - tf).cwiseAbs().maxCoeff() / tf.cwiseAbs().maxCoeff();
  const double strength_error = (qs - qf).cwiseAbs().maxCoeff() / qf.cwiseAbs().maxCoeff();
  EXPECT_LE(transfer_error, 1e-9);
  EXPECT_LE(strength_error, 1e-9);
  RecordProperty("split_error_transfer", scientific(transfer_error));
  RecordProperty("split_error_strengths", scientific(strength_error));
}

}  // namespace
}  // namespace rollnoise
