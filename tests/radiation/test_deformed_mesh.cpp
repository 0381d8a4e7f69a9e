// The radiating geometry of the loaded tyre (issue 10 §2, tyre_surface_mesh.hpp): flattened over
// the contact patch, the axle lowered by the indentation, the belt's deflected shape beyond the
// patch. The mesh must be a closed, consistently oriented surface (every edge shared by exactly
// two faces, in opposite directions), satisfy the divergence theorem (Σ n ΔS = 0 and
// Σ n·x ΔS / 3 = the enclosed volume, against a quadrature of the shape that knows nothing of
// the mesh), put the patch where the contact solution has it, and reproduce the field of a
// monopole inside it at the CPX and SPB microphones.
#include <cmath>
#include <complex>
#include <cstdio>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "radiation/belt_sampling.hpp"
#include "radiation/equivalent_sources.hpp"
#include "radiation/tyre_radiation.hpp"
#include "radiation/tyre_surface_mesh.hpp"
#include "cell_average.hpp"

namespace rollnoise {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = std::numbers::pi;

std::string scientific(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3e", x);
  return text;
}

// The radiation stage's default mesh (tyre_sound.cpp), deformed with the demo tyre's patch.
TyreSurfaceMeshSpec default_deformed() {
  TyreSurfaceMeshSpec s;
  s.geometry = TyreGeometry::deformed;
  s.across = 16;
  s.contact_refinement = 10.0;
  return s;
}

struct Named {
  std::string name;
  TyreSurfaceMeshSpec spec;
};

std::vector<Named> meshes() {
  std::vector<Named> out;
  out.push_back({"deformed default", default_deformed()});
  TyreSurfaceMeshSpec undeformed = default_deformed();
  undeformed.geometry = TyreGeometry::undeformed;
  out.push_back({"undeformed default", undeformed});
  out.push_back({"undeformed uniform", TyreSurfaceMeshSpec{}});
  TyreSurfaceMeshSpec coarse = default_deformed();
  coarse.across = 7;
  coarse.around = 48;
  coarse.sidewall_rings = 5;
  coarse.contact_refinement = 4.0;
  out.push_back({"deformed coarse, 7 across", coarse});
  TyreSurfaceMeshSpec wide = default_deformed();
  wide.deformation.patch_width = wide.width;  // the whole width in contact: no shoulders
  wide.deformation.patch_length = 0.2;        // longer than the geometric chord: the ring bulges
  wide.deformation.indentation = 0.01;
  out.push_back({"deformed, full width, long patch", wide});
  TyreSurfaceMeshSpec soft = default_deformed();
  soft.deformation.belt_tension = 1.0e3;  // complex roots: an oscillating decay
  soft.source_stride = 3;
  out.push_back({"deformed, oscillating belt, stride 3", soft});
  return out;
}

TEST(DeformedTyreMesh, ClosedAndConsistentlyOriented) {
  for (const Named& m : meshes()) {
    const TyreSurfaceMesh mesh = make_tyre_surface_mesh(m.spec);
    ASSERT_EQ(static_cast<Eigen::Index>(mesh.faces.size()), mesh.points.cols()) << m.name;
    // Every directed edge once, and its reverse once: each edge in exactly two faces, which
    // run along it in opposite directions.
    std::map<std::pair<int, int>, int> directed;
    for (const auto& face : mesh.faces) {
      ASSERT_GE(face.size(), 3u) << m.name;
      for (std::size_t i = 0; i < face.size(); ++i) {
        const int a = face[i], b = face[(i + 1) % face.size()];
        ASSERT_NE(a, b) << m.name;
        ++directed[{a, b}];
      }
    }
    int bad = 0;
    for (const auto& [edge, count] : directed) {
      const auto reverse = directed.find({edge.second, edge.first});
      if (count != 1 || reverse == directed.end() || reverse->second != 1) ++bad;
    }
    EXPECT_EQ(bad, 0) << m.name << ": edges not shared by exactly two opposite faces";
    // Every vertex used; Euler characteristic of a sphere, V − E + F = 2.
    std::vector<bool> used(static_cast<std::size_t>(mesh.vertices.cols()), false);
    for (const auto& face : mesh.faces)
      for (int v : face) used[static_cast<std::size_t>(v)] = true;
    EXPECT_EQ(std::count(used.begin(), used.end(), false), 0) << m.name;
    const auto euler = mesh.vertices.cols() - static_cast<Eigen::Index>(directed.size() / 2) +
                       static_cast<Eigen::Index>(mesh.faces.size());
    EXPECT_EQ(euler, 2) << m.name;
    // Everything above the road.
    EXPECT_GE(mesh.vertices.row(2).minCoeff(), m.spec.clearance - 1e-12) << m.name;
    EXPECT_GT(mesh.sources.row(2).minCoeff(), m.spec.clearance) << m.name;
    RecordProperty(m.name + "_faces", std::to_string(mesh.faces.size()));
  }
}

TEST(DeformedTyreMesh, DivergenceTheorem) {
  for (const Named& m : meshes()) {
    const TyreSurfaceMesh mesh = make_tyre_surface_mesh(m.spec);
    const TyreSurfaceShape shape(m.spec);
    const double total_area = mesh.areas.sum();
    // ∮ n dS = 0, with the collocation normals and areas the solver uses.
    const Eigen::Vector3d flux = mesh.normals * mesh.areas;
    EXPECT_LE(flux.norm() / total_area, 1e-12) << m.name;
    // ∮ n·x dS / 3 = V: with the collocation points, and for the polygon faces exactly (the
    // polyhedron's own volume), against the quadrature of the shape.
    double collocation = 0.0;
    for (Eigen::Index i = 0; i < mesh.points.cols(); ++i)
      collocation += mesh.normals.col(i).dot(mesh.points.col(i)) * mesh.areas(i) / 3.0;
    double polyhedron = 0.0;
    for (const auto& face : mesh.faces)
      for (std::size_t i = 1; i + 1 < face.size(); ++i)
        polyhedron += mesh.vertices.col(face[0]).dot(mesh.vertices.col(face[i]).cross(mesh.vertices.col(face[i + 1]))) / 6.0;
    const double volume = shape.volume();
    const double collocation_error = std::abs(collocation - volume) / volume;
    const double polyhedron_error = std::abs(polyhedron - volume) / volume;
    // Measured 3.2e-4 (collocation) and 6.4e-4 (polyhedron, inscribed in the curved surface) on
    // the default deformed mesh, 1.2e-3 and 2.4e-3 on the coarse one (48 around): O(h²).
    const double tolerance = m.spec.around >= 96 ? 1e-3 : 4e-3;
    EXPECT_LE(collocation_error, tolerance) << m.name;
    EXPECT_LE(polyhedron_error, tolerance) << m.name;
    RecordProperty(m.name + "_flux", scientific(flux.norm() / total_area));
    RecordProperty(m.name + "_volume_m3", scientific(volume));
    RecordProperty(m.name + "_volume_error_collocation", scientific(collocation_error));
    RecordProperty(m.name + "_volume_error_polyhedron", scientific(polyhedron_error));
    // The quadrature itself against the cylinder's πR²b (undeformed).
    if (m.spec.geometry == TyreGeometry::undeformed) {
      EXPECT_NEAR(volume, kPi * m.spec.radius * m.spec.radius * m.spec.width, 1e-9 * volume) << m.name;
    }
  }
}

TEST(DeformedTyreMesh, FlatPatchHasTheContactSolutionsLengthAndWidth) {
  for (const Named& m : meshes()) {
    if (m.spec.geometry != TyreGeometry::deformed) continue;
    const TyreSurfaceMesh mesh = make_tyre_surface_mesh(m.spec);
    const TyreDeformation& d = m.spec.deformation;
    const double c = m.spec.clearance;
    // The vertices on the road: their extent along x and across.
    double x0 = 1, x1 = -1, y0 = 1, y1 = -1;
    for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
      if (mesh.vertices(2, v) > c + 1e-12) continue;
      x0 = std::min(x0, mesh.vertices(0, v));
      x1 = std::max(x1, mesh.vertices(0, v));
      y0 = std::min(y0, mesh.vertices(1, v));
      y1 = std::max(y1, mesh.vertices(1, v));
    }
    // The cell size at the patch edges and across.
    const double cell_along = m.spec.radius * (mesh.tread_angle_edges[1] - mesh.tread_angle_edges[0]);
    double cell_across = 0.0;
    for (std::size_t k = 0; k + 1 < mesh.tread_row_edges.size(); ++k)
      cell_across = std::max(cell_across, mesh.tread_row_edges[k + 1] - mesh.tread_row_edges[k]);
    EXPECT_NEAR(x1 - x0, d.patch_length, cell_along) << m.name;
    EXPECT_NEAR(0.5 * (x0 + x1), 0.0, 1e-12) << m.name;
    EXPECT_NEAR(y1 - y0, std::min(d.patch_width, m.spec.width), cell_across) << m.name;
    RecordProperty(m.name + "_flat_length_m", scientific(x1 - x0));
    RecordProperty(m.name + "_flat_width_m", scientific(y1 - y0));
    // The patch's cells: on the road, normals straight down; the next cells off it.
    for (int c_row = mesh.flat_row_begin; c_row < mesh.flat_row_end; ++c_row)
      for (int a = 0; a < mesh.patch_cells; ++a) {
        const Eigen::Index i = a + static_cast<Eigen::Index>(mesh.tread_around) * c_row;
        EXPECT_NEAR(mesh.points(2, i), c, 1e-12) << m.name;
        EXPECT_NEAR(mesh.normals(2, i), -1.0, 1e-12) << m.name;
      }
    const Eigen::Index after = mesh.patch_cells + static_cast<Eigen::Index>(mesh.tread_around) * (m.spec.across / 2);
    EXPECT_GT(mesh.points(2, after), c + 1e-7) << m.name;
    // The axle lowered by the indentation.
    EXPECT_NEAR(mesh.axle_height, m.spec.radius - d.indentation + c, 1e-15) << m.name;
  }
}

TEST(DeformedTyreMesh, SurfaceIsTangentContinuousAtThePatchEdges) {
  // C¹: the tangent along the centre row just inside and just outside the patch edge agree
  // (to the finite-difference step), and far from the patch the tyre is the circle again.
  const TyreSurfaceMeshSpec spec = default_deformed();
  const TyreSurfaceShape shape(spec);
  const double psi0 = shape.patch_half_angle();
  const auto tangent = [&](double psi) {
    return Eigen::Vector3d(shape.position(psi + 1e-7, 0.0) - shape.position(psi - 1e-7, 0.0)).normalized();
  };
  const double kink = std::acos(std::min(1.0, tangent(psi0 - 2e-7).dot(tangent(psi0 + 2e-7))));
  EXPECT_LE(kink, 1e-4);
  RecordProperty("edge_kink_rad", scientific(kink));
  EXPECT_NEAR(shape.radius(kPi, 0.0), spec.radius, 1e-4);
  EXPECT_NEAR(shape.radius(0.5 * kPi, 0.0), spec.radius, 2e-3);
  EXPECT_GT(shape.lowest_gap_outside_patch(), 0.0);
  // The gap 5 cm ahead of the patch edge (where the horn test puts its source).
  const double a = 0.5 * spec.deformation.patch_length;
  double gap = 0.0;
  for (double psi = psi0; psi < 1.0; psi += 1e-5)
    if (shape.position(psi, 0.0).x() >= a + 0.05) {
      gap = shape.position(psi, 0.0).z();
      break;
    }
  RecordProperty("gap_5cm_ahead_m", scientific(gap));
  EXPECT_GT(gap, 0.004);
}

TEST(DeformedTyreMesh, BeltSamplingKeepsVolumeVelocity) {
  // The belt's fixed positions (512 × 20) onto the deformed tread: each cell the mean of the belt
  // cells it covers (material angle ψ, rows by the mesh's row edges), so a constant stays
  // constant and Σ v·ΔS over the material areas RΔψΔy is kept; the deformed cells' areas differ
  // from their material ones by the belt's stretch, measured here.
  const int around = 512, across = 20;
  const TyreSurfaceMeshSpec spec = default_deformed();
  const TyreSurfaceMesh mesh = make_tyre_surface_mesh(spec);
  const Eigen::SparseMatrix<double> s = belt_to_tread_matrix(around, across, mesh);
  const Eigen::VectorXd ones = s * Eigen::VectorXd::Ones(around * across);
  EXPECT_LE((ones.array() - 1.0).abs().maxCoeff(), 1e-12);
  Eigen::VectorXd field(around * across);
  for (int g = 0; g < around; ++g)
    for (int j = 0; j < across; ++j) field(j + across * g) = std::sin(0.37 * g) * (1.0 + 0.1 * j) + (g == 0 ? 5.0 : 0.0);
  const Eigen::VectorXd sampled = s * field;
  Eigen::VectorXd material(mesh.tread_points);
  double stretch = 0.0, flat_stretch = 0.0;
  for (int c = 0; c < mesh.tread_across; ++c)
    for (int a = 0; a < mesh.tread_around; ++a) {
      const auto i = static_cast<std::size_t>(a);
      const double area = spec.radius * (mesh.tread_angle_edges[i + 1] - mesh.tread_angle_edges[i]) *
                          (mesh.tread_row_edges[static_cast<std::size_t>(c) + 1] - mesh.tread_row_edges[static_cast<std::size_t>(c)]);
      const Eigen::Index m = a + static_cast<Eigen::Index>(mesh.tread_around) * c;
      material(m) = area;
      const double ratio = std::abs(mesh.areas(m) / area - 1.0);
      stretch = std::max(stretch, ratio);
      if (a < mesh.patch_cells && c >= mesh.flat_row_begin && c < mesh.flat_row_end) flat_stretch = std::max(flat_stretch, ratio);
    }
  const double band = 2 * kPi * spec.radius * spec.width;
  EXPECT_NEAR(sampled.dot(material) / band, field.sum() / (around * across), 1e-12);
  EXPECT_LE(flat_stretch, 1e-12);
  EXPECT_LE(stretch, 0.05);
  RecordProperty("largest_area_stretch", scientific(stretch));
  // The belt cell at the bottom lands in the patch's middle cells; one at the patch's leading
  // edge in the cells around it.
  Eigen::VectorXd spot = Eigen::VectorXd::Zero(around * across);
  for (int j = 0; j < across; ++j) spot(j) = 1.0;
  const Eigen::VectorXd at_bottom = s * spot;
  for (Eigen::Index m = 0; m < mesh.tread_points; ++m)
    if (at_bottom(m) > 0.0) {
      const auto a = static_cast<std::size_t>(m % mesh.tread_around);
      EXPECT_LE(mesh.tread_angle_edges[a], kPi / around);
      EXPECT_GE(mesh.tread_angle_edges[a + 1], -kPi / around);
    }
}

// The field of a monopole inside the loaded tyre over the road, from its normal velocity on
// the mesh, at the CPX microphones (front, rear), towards SPB, and ahead in the tyre's plane: on
// the mesh and with the sources the radiation stage uses at each frequency (tyre_radiation.hpp:
// the default mesh up to 4.15 kHz, the top of its band, above it the tread split in 2 with 21
// sidewall rings; monopoles up to 3 kHz, combined sources above). Asserted within 6 % (issue 10
// §3) at each band's top and at 1, 3, 4 and 5 kHz.
TEST(DeformedTyreMesh, ReproducesAnInteriorMonopolesField) {
  TyreRadiationSettings settings;
  settings.mesh = default_deformed();
  settings.max_frequency_hz = 5623.4;  // the 5 kHz band's upper edge
  const std::vector<RadiationMeshLevel> levels = radiation_mesh_levels(settings);
  ASSERT_EQ(levels.size(), 2u);
  const Medium air;
  struct Source {
    const char* name;
    Eigen::Vector3d at;
  };
  const std::vector<Source> sources{{"centre", {0.05, 0.02, 0.3}}, {"near_edge", {0.06, 0.0, 0.012}}};
  Eigen::Matrix3Xd receivers(3, 5);
  receivers << 0.2, -0.2, 0.0, 0.6, 0.5,  // CPX front and rear, SPB, ahead low, ahead in the plane
      0.29, 0.29, 7.5, 0.0, 0.0,           //
      0.1, 0.1, 1.2, 0.05, 0.1;
  std::size_t current = levels.size();
  TyreSurfaceMesh mesh;
  std::optional<EquivalentSources> model;
  for (double f : {1000.0, 3000.0, 4000.0, levels[0].top_hz, 5000.0, 5623.4}) {
    std::size_t level = 0;
    while (level + 1 < levels.size() && f > levels[level].top_hz) ++level;
    if (level != current) {
      current = level;
      mesh = make_tyre_surface_mesh(levels[level].spec);
    }
    // Monopoles up to 3 kHz, combined sources above (tyre_radiation.hpp).
    model.emplace(make_tyre_model(mesh, air, f > kCombinedSourcesAboveHz));
    ASSERT_EQ(model->symmetry_blocks(), 4);
    const TyreSurfaceShape shape(levels[level].spec);
    const double omega = 2 * kPi * f, k = omega / air.sound_speed;
    const EquivalentSourceSolve solve = model->solve(omega);
    const Eigen::MatrixXcd transfer = solve.transfer(model->pressure_matrix(omega, receivers));
    for (const Source& src : sources) {
      Eigen::VectorXcd v(mesh.points.cols());
      for (Eigen::Index m = 0; m < v.size(); ++m)
        v(m) = -normal_gradient(shape, mesh, m, src.at, k);  // cell means on the tread
      const Eigen::VectorXcd p = transfer * v;
      double worst = 0.0;
      for (Eigen::Index r = 0; r < receivers.cols(); ++r) {
        const Complex exact = Complex(0.0, omega * air.density) * helmholtz_green(receivers.col(r), src.at, k, true);
        const double error = std::abs(p(r) - exact) / std::abs(exact);
        worst = std::max(worst, error);
        RecordProperty(std::string(src.name) + "_" + std::to_string(static_cast<int>(f)) + "Hz_r" + std::to_string(r),
                       scientific(error));
      }
      EXPECT_LE(worst, 0.06) << src.name << " at " << f << " Hz (mesh " << level << ")";
      std::printf("%s, %.0f Hz (mesh %zu, %ld points): worst %.2f %%\n", src.name, f, level,
                  static_cast<long>(mesh.points.cols()), 100.0 * worst);
    }
  }
}

}  // namespace
}  // namespace rollnoise
