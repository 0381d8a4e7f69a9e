#pragma once
// The normal derivative of a point source's field over the tyre mesh's cells, as the radiation
// stage sees a velocity field: on the tread the mean over each cell (what belt_sampling.hpp
// gives the mesh), on the sidewalls the point value.
#include <algorithm>
#include <cmath>
#include <complex>

#include "radiation/equivalent_sources.hpp"
#include "radiation/tyre_surface_mesh.hpp"

namespace rollnoise {

// n·∇G at collocation point m for a source at `s`: on the tread the area-weighted mean over the
// point's cell on the (deformed or undeformed) surface (sub-sampled finer where the source is
// close), on the sidewalls the point value.
// `gradient(x)`: ∇_x G of the source's field (default: the free field and its image in the rigid road).
template <class Gradient>
inline std::complex<double> normal_gradient(const TyreSurfaceShape& shape, const TyreSurfaceMesh& mesh, Eigen::Index m,
                                            const Eigen::Vector3d& s, const Gradient& gradient) {
  const Eigen::Vector3cd normal = mesh.normals.col(m).cast<std::complex<double>>();
  if (m >= mesh.tread_points) return normal.dot(gradient(Eigen::Vector3d(mesh.points.col(m))));
  const auto a = static_cast<std::size_t>(m % mesh.tread_around);
  const auto b = static_cast<std::size_t>(m / mesh.tread_around);
  const double psi0 = mesh.tread_angle_edges[a], psi1 = mesh.tread_angle_edges[a + 1];
  const double y0 = mesh.tread_row_edges[b], y1 = mesh.tread_row_edges[b + 1];
  const double distance = (mesh.points.col(m) - s).norm();
  const auto subdivisions = [&](double size) { return std::clamp(static_cast<int>(std::ceil(4.0 * size / distance)), 1, 64); };
  const double radius = (mesh.points.col(m) - Eigen::Vector3d(0.0, mesh.points(1, m), mesh.axle_height)).norm();
  const int na = subdivisions(radius * (psi1 - psi0)), nb = subdivisions(y1 - y0);
  std::complex<double> sum = 0.0;
  double weight = 0.0;
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j) {
      const double psi = psi0 + (i + 0.5) * (psi1 - psi0) / na, y = y0 + (j + 0.5) * (y1 - y0) / nb;
      const double w = shape.area_element(psi, y);
      sum += w * shape.normal(psi, y).cast<std::complex<double>>().dot(gradient(shape.position(psi, y)));
      weight += w;
    }
  return sum / weight;
}

inline std::complex<double> normal_gradient(const TyreSurfaceShape& shape, const TyreSurfaceMesh& mesh, Eigen::Index m,
                                            const Eigen::Vector3d& s, double k) {
  return normal_gradient(shape, mesh, m, s, [&](const Eigen::Vector3d& x) { return helmholtz_green_gradient(x, s, k, true); });
}

}  // namespace rollnoise
