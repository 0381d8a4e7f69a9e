// The horn effect (Kropp, Becot & Barrelet, Acustica 86, 2000; Graf, Kuo & Dowling, JSV 256,
// 2002): a point source in the wedge between tread and road, a few cm ahead of the contact line,
// is heard in front of the tyre 10–20 dB louder at 1–3 kHz than the same source over the road
// with no tyre. The equivalent-source model gives the field scattered by the rigid tyre: the
// incident field (monopole + image) has normal velocity v_inc on the tyre's surface, the
// scattered field the velocity −v_inc, and the amplification is
//   ΔL = 20 log |p_inc + p_scat| / |p_inc|   at a receiver in the tyre's plane ahead of it.
//
// Two things make this hard for the mesh, both measured while writing the test:
//  - along the tread, the wedge's gap is a few mm (c + s²/2R): the uniform 2 cm mesh misses it,
//    the graded mesh (contact_refinement) resolves it;
//  - across, the source's field on the tread is a spot a few mm wide: with the default 8 rows
//    (2.25 cm apart) the answer depended on where the rows fell (0–13 dB); 16 rows (1.1 cm) and
//    the tread's incident velocity taken as the mean over each cell, which is what the belt's
//    sampling gives the mesh in a simulation (belt_sampling.hpp), made it converge.
// A second, independent estimate checks the first: by reciprocity, the source at the receiver and
// the pressure in the horn (the scattered field then comes from a smooth incident field, but is
// needed 3 mm from the surface). Both agree within 1 dB at 1 kHz and 3.1 dB at 2 kHz on the
// graded mesh; at 3 kHz the amplification is recorded, not asserted.
// The same three checks (reciprocity, refinement, an interior monopole's field) on the loaded
// tyre, flattened over the contact patch (tyre_surface_mesh.hpp), with the source 5 cm ahead of
// the patch's leading edge: there the 2 kHz value is recorded, not claimed (the two estimates
// are 3–4 dB apart).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "radiation/equivalent_sources.hpp"
#include "radiation/tyre_radiation.hpp"
#include "radiation/tyre_surface_mesh.hpp"
#include "cell_average.hpp"

namespace rollnoise {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = std::numbers::pi;

// The horn source: 5 cm ahead of the contact line, 3 mm above the road, in the centre plane
// (the gap there is 6 mm). Receivers in the tyre's plane ahead of it.
const Eigen::Vector3d kHornSource(0.05, 0.0, 0.003);
Eigen::Matrix3Xd horn_receivers() {
  Eigen::Matrix3Xd r(3, 3);
  r << 0.5, 1.0, 0.5,  //
      0.0, 0.0, 0.0,   //
      0.05, 0.1, 0.2;
  return r;
}
// The source inside the tyre for the interior check: near the contact, 8.6 mm inside the tread
// (whose surface is 3.4 mm above the road at x = 3 cm). Not the off-centre source of
// test_tyre_radiation.cpp, which radiates mostly through the sidewalls: these are too coarse
// here for it (measured 31–38 % at 3 kHz; the default 12 rings pass that test).
const Eigen::Vector3d kInsideNearContact(0.03, 0.0, 0.012);

// The mesh the horn needs: graded towards the contact (2 mm cells at the bottom), 16 rows across,
// coarser sidewalls (8 rings, 4 cm: they are far from the source) to keep the test short.
TyreSurfaceMeshSpec graded_spec(double refinement) {
  TyreSurfaceMeshSpec s;
  s.contact_refinement = refinement;
  s.across = 16;
  s.sidewall_rings = 8;
  return s;
}

struct HornResult {
  std::vector<double> direct_db;      // per receiver: amplification, source in the horn
  std::vector<double> reciprocal_db;  // per receiver: source at the receiver, pressure in the horn
  std::vector<double> interior_error; // relative error of the interior source's field at the
                                      // receivers and at the horn point (R + 1)
  double seconds = 0.0;
};

HornResult solve_horn(const TyreSurfaceMeshSpec& spec, double f) {
  const auto started = std::chrono::steady_clock::now();
  const TyreSurfaceMesh mesh = make_tyre_surface_mesh(spec);
  const TyreSurfaceShape shape(spec);
  const bool deformed = spec.geometry == TyreGeometry::deformed;
  // Deformed: the horn source 5 cm ahead of the patch's leading edge, the interior source above
  // the edge, 1 cm inside the tread.
  const double edge = deformed ? 0.5 * spec.deformation.patch_length : 0.0;
  const Eigen::Vector3d horn_source = kHornSource + Eigen::Vector3d(edge, 0.0, 0.0);
  const Eigen::Vector3d inside = deformed ? Eigen::Vector3d(edge, 0.0, spec.clearance + 0.01) : kInsideNearContact;
  // As the radiation stage solves it (tyre_radiation.hpp): monopoles up to 3 kHz, combined
  // sources above.
  const EquivalentSources model = make_tyre_model(mesh, Medium{}, f > kCombinedSourcesAboveHz);
  const Medium air;
  const double omega = 2 * kPi * f, k = omega / air.sound_speed;
  const Complex iwr(0.0, omega * air.density);
  const Eigen::Matrix3Xd receivers = horn_receivers();
  const Eigen::Index nr = receivers.cols();
  // Surface velocities (unit volume velocity): column 0 the scattered field's −v_inc of the horn
  // source, 1 … R those of a source at each receiver, then the interior source's own +v.
  Eigen::MatrixXcd v(mesh.points.cols(), nr + 2);
  for (Eigen::Index m = 0; m < v.rows(); ++m) {
    v(m, 0) = normal_gradient(shape, mesh, m, horn_source, k);  // −v_inc = +n·∇G
    for (Eigen::Index r = 0; r < nr; ++r) v(m, 1 + r) = normal_gradient(shape, mesh, m, receivers.col(r), k);
    v(m, nr + 1) = -normal_gradient(shape, mesh, m, inside, k);
  }
  const Eigen::MatrixXcd q = model.solve(omega).strengths(v);
  Eigen::Matrix3Xd at(3, nr + 1);
  at << receivers, horn_source;
  const Eigen::MatrixXcd p = model.pressure_matrix(omega, at) * q;
  HornResult out;
  for (Eigen::Index r = 0; r < nr; ++r) {
    const Complex incident = iwr * helmholtz_green(receivers.col(r), horn_source, k, true);
    out.direct_db.push_back(20.0 * std::log10(std::abs(incident + p(r, 0)) / std::abs(incident)));
    out.reciprocal_db.push_back(20.0 * std::log10(std::abs(incident + p(nr, 1 + r)) / std::abs(incident)));
  }
  for (Eigen::Index r = 0; r <= nr; ++r) {
    const Complex exact = iwr * helmholtz_green(at.col(r), inside, k, true);
    out.interior_error.push_back(std::abs(p(r, nr + 1) - exact) / std::abs(exact));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return out;
}

// Each (mesh, frequency) is solved once for all the tests below (a few seconds each).
const HornResult& horn(const std::string& name, const TyreSurfaceMeshSpec& spec, double f) {
  static std::map<std::pair<std::string, double>, HornResult> cache;
  const auto key = std::make_pair(name, f);
  auto found = cache.find(key);
  if (found == cache.end()) found = cache.emplace(key, solve_horn(spec, f)).first;
  return found->second;
}

void record(const std::string& name, double f, const HornResult& r) {
  std::string prefix = name;
  prefix += "_";
  prefix += std::to_string(static_cast<int>(f));
  prefix += "Hz";
  for (std::size_t i = 0; i < r.direct_db.size(); ++i) {
    std::string key = prefix;
    key += "_r";
    key += std::to_string(i);
    ::testing::Test::RecordProperty(key + "_dB", std::to_string(r.direct_db[i]));
    ::testing::Test::RecordProperty(key + "_reciprocal_dB", std::to_string(r.reciprocal_db[i]));
  }
  ::testing::Test::RecordProperty(prefix + "_seconds", std::to_string(r.seconds));
}

TEST(HornEffect, GradedMeshResolvesFieldsNearTheContact) {
  // A field known exactly, that of a monopole inside the tyre over the road, rebuilt from its
  // normal velocity on the graded mesh at 3 kHz: at the receivers and at the horn point, 3 mm
  // from the tread. Measured 0.7–1.0 % at the receivers, 4.1 % at the horn point.
  const HornResult& r = horn("graded", graded_spec(10.0), 3000.0);
  for (std::size_t i = 0; i < r.interior_error.size(); ++i) {
    EXPECT_LE(r.interior_error[i], 0.06) << "check " << i;
    RecordProperty("interior_error_3000Hz_" + std::to_string(i), std::to_string(r.interior_error[i]));
  }
  record("graded", 3000.0, r);
}

TEST(HornEffect, GradedMeshShowsTheHornAmplification) {
  const Eigen::Index nr = horn_receivers().cols();
  const HornResult& uniform = horn("uniform", TyreSurfaceMeshSpec{}, 1000.0);
  record("uniform", 1000.0, uniform);
  for (double f : {1000.0, 2000.0}) {
    const HornResult& r = horn("graded", graded_spec(10.0), f);
    record("graded", f, r);
    for (Eigen::Index i = 0; i < nr; ++i) {
      const auto u = static_cast<std::size_t>(i);
      // Measured 16.4–17.9 dB (1 kHz) and 10.3–13.1 dB (2 kHz): within the 10–20 dB reported.
      EXPECT_GE(r.direct_db[u], 10.0) << f << " Hz, receiver " << i;
      EXPECT_LE(r.direct_db[u], 20.0) << f << " Hz, receiver " << i;
      // Reciprocity: the two estimates agree (measured within 0.9 dB at 1 kHz, 1.7–3.1 dB at
      // 2 kHz; with the sources 1.5 cell sides deep, 2.3 dB before).
      EXPECT_NEAR(r.direct_db[u], r.reciprocal_db[u], f < 1500.0 ? 3.0 : 3.5) << f << " Hz, receiver " << i;
      // The default uniform mesh misses most of it (measured 3.9–4.4 dB at 1 kHz).
      if (f == 1000.0) {
        EXPECT_GE(r.direct_db[u] - uniform.direct_db[u], 6.0) << "receiver " << i;
      }
    }
  }
}

TEST(HornEffect, AmplificationConvergesWithTheContactSpacing) {
  // Halving the spacing at the contact (2.1 → 1.0 mm) lowers the 1 kHz amplification by
  // measured 1.2–1.4 dB: converged to within that, not better.
  const HornResult& coarse = horn("graded", graded_spec(10.0), 1000.0);
  const HornResult& fine = horn("graded_x2", graded_spec(20.0), 1000.0);
  record("graded_x2", 1000.0, fine);
  for (std::size_t i = 0; i < coarse.direct_db.size(); ++i) {
    EXPECT_LE(std::abs(fine.direct_db[i] - coarse.direct_db[i]), 2.5) << "receiver " << i;
    EXPECT_GE(fine.direct_db[i], 10.0) << "receiver " << i;
    RecordProperty("convergence_1000Hz_r" + std::to_string(i) + "_dB", std::to_string(fine.direct_db[i] - coarse.direct_db[i]));
  }
}

// The loaded tyre (issue 10 §2): flattened over the demo's patch (0.119 m × 0.14 m, 14.9 mm
// indentation), the horn starting where the tread leaves the road. The source 5 cm ahead of the
// patch's leading edge, 3 mm above the road (the gap there is 12 mm); the same receivers.
TyreSurfaceMeshSpec deformed_spec(double refinement, double clearance = 0.002) {
  TyreSurfaceMeshSpec s = graded_spec(refinement);
  s.geometry = TyreGeometry::deformed;
  s.clearance = clearance;
  return s;
}

TEST(HornEffect, DeformedMeshResolvesFieldsNearThePatchEdge) {
  // A monopole 1 cm inside the tread above the patch's leading edge: its field at the receivers
  // and at the horn point, at 3 kHz on this mesh, and at 5 kHz and 5623 Hz (the 5 kHz band's
  // upper edge) on the mesh the radiation stage takes there (the tread split in 2, 21 sidewall
  // rings; tyre_radiation.hpp). Measured 0.6–1.6 % at 3 kHz; 0.5–0.7 % at 5 kHz, 0.5–1.4 % at
  // 5623 Hz.
  TyreRadiationSettings settings;
  settings.mesh = deformed_spec(10.0);
  settings.max_frequency_hz = 5623.4;
  const std::vector<RadiationMeshLevel> levels = radiation_mesh_levels(settings);
  ASSERT_EQ(levels.size(), 2u);
  for (double f : {3000.0, 5000.0, 5623.4}) {
    const bool split = f > levels[0].top_hz;
    const HornResult& r = split ? horn("deformed_split", levels[1].spec, f) : horn("deformed", deformed_spec(10.0), f);
    for (std::size_t i = 0; i < r.interior_error.size(); ++i) {
      EXPECT_LE(r.interior_error[i], 0.06) << "check " << i << " at " << f << " Hz";
      RecordProperty("deformed_interior_error_" + std::to_string(static_cast<int>(f)) + "Hz_" + std::to_string(i),
                     std::to_string(r.interior_error[i]));
    }
  }
}

TEST(HornEffect, DeformedMeshShowsTheHornAmplification) {
  const Eigen::Index nr = horn_receivers().cols();
  for (double f : {500.0, 1000.0, 2000.0, 3000.0}) {
    const HornResult& r = horn("deformed", deformed_spec(10.0), f);
    record("deformed", f, r);
    // The undeformed figures beside them (docs/physics/radiation.md, "The horn").
    record("graded", f, horn("graded", graded_spec(10.0), f));
    for (Eigen::Index i = 0; i < nr; ++i) {
      const auto u = static_cast<std::size_t>(i);
      if (f == 1000.0) {
        // Measured 13.7–14.6 dB, the reciprocal estimate within 1.0 dB of it.
        EXPECT_GE(r.direct_db[u], 10.0) << f << " Hz, receiver " << i;
        EXPECT_LE(r.direct_db[u], 20.0) << f << " Hz, receiver " << i;
        EXPECT_NEAR(r.direct_db[u], r.reciprocal_db[u], 2.0) << f << " Hz, receiver " << i;
      } else if (f == 2000.0) {
        // Measured 5.4–7.9 dB, the reciprocal 9.7–11.7 dB (4.2–4.3 dB apart; with 32 rows
        // across 4.5–6.3 and 7.1–9.9 dB): recorded, not claimed; both between 3 and 15 dB.
        EXPECT_GE(std::min(r.direct_db[u], r.reciprocal_db[u]), 3.0) << f << " Hz, receiver " << i;
        EXPECT_LE(std::max(r.direct_db[u], r.reciprocal_db[u]), 15.0) << f << " Hz, receiver " << i;
      }
    }
  }
}

TEST(HornEffect, DeformedAmplificationConvergesWithTheEdgeSpacing) {
  // Halving the cells at the patch edges (2.1 → 1.0 mm): measured +0.4 … +0.7 dB at 1 kHz,
  // +0.6 … +0.8 dB at 2 kHz.
  for (double f : {1000.0, 2000.0}) {
    const HornResult& coarse = horn("deformed", deformed_spec(10.0), f);
    const HornResult& fine = horn("deformed_x2", deformed_spec(20.0), f);
    record("deformed_x2", f, fine);
    for (std::size_t i = 0; i < coarse.direct_db.size(); ++i) {
      EXPECT_LE(std::abs(fine.direct_db[i] - coarse.direct_db[i]), 2.5) << f << " Hz, receiver " << i;
      RecordProperty("deformed_convergence_" + std::to_string(static_cast<int>(f)) + "Hz_r" + std::to_string(i) + "_dB",
                     std::to_string(fine.direct_db[i] - coarse.direct_db[i]));
    }
  }
}

TEST(HornEffect, DeformedAmplificationDependsLittleOnTheClearance) {
  // The flat lies 2 mm above the road (the equivalent sources need a gap between the body and
  // its image); 1 mm and 4 mm instead: measured +0.3 dB and −0.8 dB at 1 kHz.
  const HornResult& base = horn("deformed", deformed_spec(10.0), 1000.0);
  for (double c : {0.001, 0.004}) {
    const std::string name = "deformed_c" + std::to_string(static_cast<int>(c * 1000.0)) + "mm";
    const HornResult& r = horn(name, deformed_spec(10.0, c), 1000.0);
    record(name, 1000.0, r);
    for (std::size_t i = 0; i < base.direct_db.size(); ++i) {
      EXPECT_LE(std::abs(r.direct_db[i] - base.direct_db[i]), 3.0) << name << ", receiver " << i;
      RecordProperty(name + "_change_1000Hz_r" + std::to_string(i) + "_dB", std::to_string(r.direct_db[i] - base.direct_db[i]));
    }
    for (std::size_t i = 0; i < r.interior_error.size(); ++i) RecordProperty(name + "_interior_error_1000Hz_" + std::to_string(i), std::to_string(r.interior_error[i]));
  }
}

TEST(HornEffect, DeformedAmplificationWithTwiceTheRowsAcross) {
  // The horn source's spot on the tread is about as wide as the rows across are apart (12 mm on
  // the flat with 16 rows): 32 rows at 2 kHz, where the direct and reciprocal estimates differ.
  TyreSurfaceMeshSpec spec = deformed_spec(10.0);
  spec.across = 32;
  const HornResult& r = horn("deformed_32across", spec, 2000.0);
  record("deformed_32across", 2000.0, r);
  const HornResult& base = horn("deformed", deformed_spec(10.0), 2000.0);
  for (std::size_t i = 0; i < r.direct_db.size(); ++i)
    RecordProperty("deformed_32across_change_2000Hz_r" + std::to_string(i) + "_dB", std::to_string(r.direct_db[i] - base.direct_db[i]));
}

}  // namespace
}  // namespace rollnoise
