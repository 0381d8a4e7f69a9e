#include "radiation/tyre_surface_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace rollnoise {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The tread cells' widths in angle, from the bottom cell (centred on φ = 0) round to +x and back
// from −x: uniform, or graded geometrically from the bottom (tyre_surface_mesh.hpp).
std::vector<double> tread_widths(const TyreSurfaceMeshSpec& s) {
  const double uniform = kTwoPi / s.around;
  if (s.contact_refinement == 1.0) return std::vector<double>(static_cast<std::size_t>(s.around), uniform);
  const double bottom = uniform / s.contact_refinement;
  // The graded cells on each side, up to where the next would be within a growth step of the
  // uniform spacing.
  std::vector<double> graded;
  for (double w = bottom * s.contact_growth; w < uniform / std::sqrt(s.contact_growth); w *= s.contact_growth)
    graded.push_back(w);
  double rest = kTwoPi - bottom;
  for (double w : graded) rest -= 2.0 * w;
  // The rest in near-uniform cells, as many as make Na a multiple of the source stride (so every
  // row of the tread has its sources at the same angles).
  const auto fixed = static_cast<int>(1 + 2 * graded.size());
  auto count = std::max(1, static_cast<int>(std::lround(rest / uniform)));
  for (int step = 0; step < s.source_stride; ++step) {
    if ((fixed + count + step) % s.source_stride == 0) { count += step; break; }
    if (count - step >= 1 && (fixed + count - step) % s.source_stride == 0) { count -= step; break; }
  }
  std::vector<double> widths{bottom};
  widths.insert(widths.end(), graded.begin(), graded.end());
  widths.insert(widths.end(), static_cast<std::size_t>(count), rest / count);
  widths.insert(widths.end(), graded.rbegin(), graded.rend());
  return widths;
}

}  // namespace

TyreSurfaceMesh make_tyre_surface_mesh(const TyreSurfaceMeshSpec& s) {
  if (!(s.radius > 0 && s.width > 0 && s.clearance > 0) || s.around < 8 || s.across < 1 || s.sidewall_rings < 1 ||
      !(s.source_depth >= 0 && s.source_depth < 0.5 * s.width) || s.source_stride < 1)
    throw std::invalid_argument("tyre surface mesh: sizes must be positive (clearance > 0, source depth below half the width)");
  if (!(s.contact_refinement >= 1.0 && s.contact_refinement <= 1000.0) || !(s.contact_growth > 1.0 && s.contact_growth <= 2.0))
    throw std::invalid_argument("tyre surface mesh: contact refinement must be within 1 ... 1000, growth within (1, 2]");
  const double axle = s.radius + s.clearance;
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<double> areas, depths;
  // Tread band.
  const double dphi = kTwoPi / s.around;
  const double depth = s.source_depth > 0.0 ? s.source_depth : 1.5 * s.radius * dphi;  // at the uniform spacing
  const std::vector<double> widths = tread_widths(s);
  const auto around = static_cast<int>(widths.size());
  std::vector<double> edges(widths.size() + 1);
  edges[0] = -0.5 * widths[0];
  for (std::size_t a = 0; a < widths.size(); ++a) edges[a + 1] = edges[a] + widths[a];
  const double dy = s.width / s.across;
  for (int b = 0; b < s.across; ++b) {
    const double y = -0.5 * s.width + (b + 0.5) * dy;
    for (int a = 0; a < around; ++a) {
      const auto i = static_cast<std::size_t>(a);
      // Uniform: a·Δφ exactly, as before the grading existed.
      const double phi = s.contact_refinement == 1.0 ? a * dphi : 0.5 * (edges[i] + edges[i + 1]);
      points.emplace_back(s.radius * std::sin(phi), y, axle - s.radius * std::cos(phi));
      normals.emplace_back(std::sin(phi), 0.0, -std::cos(phi));
      areas.push_back(s.radius * widths[i] * dy);
      depths.push_back(depth * widths[i] / dphi);
    }
  }
  const int tread = static_cast<int>(points.size());
  // Sidewalls: rings at the centres of equal radial strips, as many points per ring as its
  // circumference allows at the tread's uniform spacing.
  for (int side : {-1, 1}) {
    for (int ring = 0; ring < s.sidewall_rings; ++ring) {
      const double r0 = s.radius * ring / s.sidewall_rings;
      const double r1 = s.radius * (ring + 1) / s.sidewall_rings;
      const double r = 0.5 * (r0 + r1);
      const int count = std::max(6, static_cast<int>(std::lround(s.around * r / s.radius)));
      for (int a = 0; a < count; ++a) {
        const double phi = kTwoPi * (a + 0.5 * (ring % 2)) / count;
        points.emplace_back(r * std::sin(phi), side * 0.5 * s.width, axle - r * std::cos(phi));
        normals.emplace_back(0.0, side, 0.0);
        areas.push_back(0.5 * (r1 * r1 - r0 * r0) * kTwoPi / count);
        depths.push_back(depth);
      }
    }
  }
  TyreSurfaceMesh mesh;
  const auto n = static_cast<Eigen::Index>(points.size());
  mesh.points.resize(3, n);
  mesh.normals.resize(3, n);
  mesh.areas.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    mesh.points.col(i) = points[static_cast<std::size_t>(i)];
    mesh.normals.col(i) = normals[static_cast<std::size_t>(i)];
    mesh.areas(i) = areas[static_cast<std::size_t>(i)];
  }
  mesh.tread_points = tread;
  mesh.tread_around = around;
  mesh.tread_across = s.across;
  mesh.tread_angle_edges = std::move(edges);
  // Sources: every stride-th collocation point of one half of the tyre, y ≤ 0, and the mirror
  // images of those on the other half, so that the sources are mirror-symmetric like the points
  // and the solve splits (equivalent_sources.hpp, MirrorPairing). Tread row c mirrors row
  // Nb − 1 − c (same angles), the +y sidewall the −y one point by point. Each point moves
  // inwards along its normal by its depth; tread sources move towards the axle: above the road,
  // however close the point is to it. When Na and the points of a sidewall are multiples of the
  // stride (the default meshes), these are the stride-th points in global order as before.
  const int sidewall = static_cast<int>(n) - tread;  // both sidewalls
  std::vector<Eigen::Index> chosen;
  for (int c = 0; c < s.across; ++c) {
    const int lower = std::min(c, s.across - 1 - c);
    for (int a = 0; a < around; ++a)
      if ((a + around * lower) % s.source_stride == 0) chosen.push_back(a + around * c);
  }
  for (int side = 0; side < 2; ++side)
    for (int j = 0; j < sidewall / 2; ++j)
      if ((tread + j) % s.source_stride == 0) chosen.push_back(tread + side * (sidewall / 2) + j);
  std::vector<Eigen::Vector3d> sources;
  for (Eigen::Index i : chosen)
    sources.emplace_back(mesh.points.col(i) - depths[static_cast<std::size_t>(i)] * mesh.normals.col(i));
  mesh.sources.resize(3, static_cast<Eigen::Index>(sources.size()));
  for (std::size_t i = 0; i < sources.size(); ++i) mesh.sources.col(static_cast<Eigen::Index>(i)) = sources[i];
  return mesh;
}

}  // namespace rollnoise
