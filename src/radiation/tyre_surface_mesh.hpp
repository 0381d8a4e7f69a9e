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
// Points, normals and sources are mirror-symmetric about the centre plane y = 0 for every spec
// (an odd `across` puts a tread row on the plane, mapped to itself), so the equivalent-source
// solve splits into two half-size problems (equivalent_sources.hpp, MirrorPairing).
//
// Graded tread (contact_refinement > 1). The horn between tread and road is a wedge whose gap is
// c + s²/2R at the arc distance s from the bottom (2 mm at the contact line, 6 mm 5 cm ahead with
// c = 2 mm, R = 0.316 m): a uniform 2 cm mesh does not see it, and a source in it is amplified
// only by a few dB instead of the 10–20 dB reported (Kropp, Becot & Barrelet, Acustica 86, 2000;
// Graf, Kuo & Dowling, JSV 256, 2002). The tread cells are then spacing/refinement wide at the
// bottom and grow geometrically by `contact_growth` per cell on both sides up to the uniform
// spacing 2πR/around, which fills the rest of the circumference. The sources keep the depth rule
// locally (1.5 of the local spacing around), so near the contact they sit a few mm inside the
// tread: the inward normal there points up, so they stay above the road (z ≥ c + depth·cos φ).
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
  double source_depth = 0.0;  // m inside the surface at the uniform spacing; 0: 1.5 tread point
                              // spacings. Graded tread: scaled with the local spacing around.
  int source_stride = 2;      // one source per this many collocation points (chosen on the half
                              // y ≤ 0 and mirrored)
  // Graded tread: the cell at the bottom is 2πR/(around·contact_refinement) wide (1: uniform,
  // Na = around); the cells grow by contact_growth per cell away from it (1 < growth ≤ 2).
  double contact_refinement = 1.0;
  double contact_growth = 1.2;
};

struct TyreSurfaceMesh {
  Eigen::Matrix3Xd points;   // collocation points, m
  Eigen::Matrix3Xd normals;  // outward unit normals
  Eigen::VectorXd areas;     // surface element of each point, m²
  Eigen::Matrix3Xd sources;  // equivalent source positions, m
  int tread_points = 0;      // the first tread_points columns are the tread band, index a + Na·b
  int tread_around = 0;      // Na
  int tread_across = 0;      // Nb
  // The tread cells' angular edges, rad from the bottom towards +x: cell a spans
  // [edges[a], edges[a + 1]] (Na + 1 values, edges[Na] = edges[0] + 2π); its point is at the
  // middle. Uniform mesh: edges[a] = (a − ½)·2π/Na.
  std::vector<double> tread_angle_edges;
};

TyreSurfaceMesh make_tyre_surface_mesh(const TyreSurfaceMeshSpec& spec);

}  // namespace rollnoise
