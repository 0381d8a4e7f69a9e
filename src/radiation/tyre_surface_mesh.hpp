#pragma once
// The tyre as a radiating body (MODEL.md §5): a cylinder of radius R and width b on its axis
// across the road (y), a clearance c above the road at its lowest line, so that the horn
// between tread and road is part of the geometry. x runs along the road in the direction of
// travel, y across from the wheel's centre plane, z up; the axle is at (0, 0, R + c).
//
// Collocation points: the tread band (Na around × Nb across, angle φ from the bottom, growing
// towards +x) and both sidewalls (flat disks). Equivalent sources sit a short depth inside the
// surface, along the inward normal: about one to two point spacings, the usual choice that keeps
// the least-squares problem well conditioned while the sources still resolve the surface's detail.
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

struct TyreSurfaceMeshSpec {
  double radius = 0.316;      // R, m
  double width = 0.18;        // b, m
  double clearance = 0.002;   // c, m, between the tread and the road at the bottom
  // About 5 points per wavelength at 3 kHz (λ = 11 cm) on the tread and on the sidewalls,
  // whose area is larger than the tread's: coarser sidewalls were the largest error.
  int around = 96;            // tread collocation points around (2.1 cm apart)
  int across = 8;             // tread collocation points across (2.3 cm)
  int sidewall_rings = 12;    // rings of collocation points on each sidewall (2.6 cm)
  double source_depth = 0.0;  // m inside the surface; 0: 1.5 tread point spacings
  int source_stride = 2;      // one source per this many collocation points
};

struct TyreSurfaceMesh {
  Eigen::Matrix3Xd points;   // collocation points, m
  Eigen::Matrix3Xd normals;  // outward unit normals
  Eigen::VectorXd areas;     // surface element of each point, m²
  Eigen::Matrix3Xd sources;  // equivalent source positions, m
  int tread_points = 0;      // the first tread_points columns are the tread band, index a + Na·b
};

TyreSurfaceMesh make_tyre_surface_mesh(const TyreSurfaceMeshSpec& spec);

}  // namespace rollnoise
