#include "radiation/tyre_surface_mesh.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rollnoise {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
}

TyreSurfaceMesh make_tyre_surface_mesh(const TyreSurfaceMeshSpec& s) {
  if (!(s.radius > 0 && s.width > 0 && s.clearance > 0) || s.around < 8 || s.across < 1 || s.sidewall_rings < 1 ||
      !(s.source_depth >= 0 && s.source_depth < 0.5 * s.width) || s.source_stride < 1)
    throw std::invalid_argument("tyre surface mesh: sizes must be positive (clearance > 0, source depth below half the width)");
  const double axle = s.radius + s.clearance;
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<double> areas;
  // Tread band.
  const double dphi = kTwoPi / s.around;
  const double dy = s.width / s.across;
  for (int b = 0; b < s.across; ++b) {
    const double y = -0.5 * s.width + (b + 0.5) * dy;
    for (int a = 0; a < s.around; ++a) {
      const double phi = a * dphi;
      points.emplace_back(s.radius * std::sin(phi), y, axle - s.radius * std::cos(phi));
      normals.emplace_back(std::sin(phi), 0.0, -std::cos(phi));
      areas.push_back(s.radius * dphi * dy);
    }
  }
  const int tread = static_cast<int>(points.size());
  // Sidewalls: rings at the centres of equal radial strips, as many points per ring as its
  // circumference allows at the tread's spacing.
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
  // Sources: every stride-th collocation point, moved inwards along its normal.
  const double depth = s.source_depth > 0.0 ? s.source_depth : 1.5 * s.radius * dphi;
  std::vector<Eigen::Vector3d> sources;
  for (Eigen::Index i = 0; i < n; i += s.source_stride) {
    const Eigen::Vector3d inward = mesh.points.col(i) - depth * mesh.normals.col(i);
    // Near the axis of a sidewall the inward step could leave the body through the other
    // side: keep sources within the cylinder.
    sources.push_back(inward);
  }
  mesh.sources.resize(3, static_cast<Eigen::Index>(sources.size()));
  for (std::size_t i = 0; i < sources.size(); ++i) mesh.sources.col(static_cast<Eigen::Index>(i)) = sources[i];
  return mesh;
}

}  // namespace rollnoise
