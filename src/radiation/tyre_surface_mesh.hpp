#pragma once
// The tyre as a radiating body (MODEL.md §5), standing on a rigid road: x runs along the road in
// the direction of travel, y across from the wheel's centre plane, z up from the road.
//
// Two geometries (TyreGeometry):
//  - undeformed: a cylinder of radius R and width b on its axis across the road, a clearance c
//    above the road at its lowest line; the axle at (0, 0, R + c).
//  - deformed: the loaded tyre. The axle is lowered by the indentation d, to R − d + c, and the
//    tread is flattened over the contact patch (length 2a and width w_c, from the contact
//    solution), where it lies on the road at the clearance c. Beyond the patch's leading and
//    trailing edges the belt returns to the undeformed circle along the deflected shape of the
//    loaded belt (TyreSurfaceShape): the free solution of the model's own belt equation along
//    the circumference, Bx w'''' − Tx w'' + s_f w = 0 (a tensioned beam on an elastic
//    foundation, MODEL.md §4), w = A e^{−k₂σ} + B e^{−k₁σ} at the arc distance σ from the edge,
//    A and B fixed by the deflection and the slope the flat leaves there, so the surface is C¹
//    at the patch edges (tangent continuous; the bending length 1/k₁ ≈ 1 cm rounds the edge and
//    the tension length 1/k₂ ≈ 14 cm carries the deflection round the tyre). Across, the rows
//    beyond the patch's width (the shoulders) are lifted off the road by a shoulder drop
//    Δ(y) = h·u² (u from 0 at the patch's side to 1 at the sidewall, C¹ with the flat), scaled
//    with the local deflection, so that far from the patch they are the cylinder again.
//    The sidewalls are flat disks at y = ±b/2 whose rim follows the tread's edge rows (each
//    disk point scaled radially with the rim).
//
// Parametrisation of the tread. A tread point is named by its material angle ψ (the belt's arc
// position s = Rψ from the bottom, in the direction of travel: the belt's fixed positions, which
// belt_sampling.hpp maps onto the mesh) and y. On the flat, x = Rψ: the contact solution's
// coordinate along the road. Outside it, the polar angle round the axle is a linear stretch of ψ
// from the patch edge to the top. Undeformed: the polar angle is ψ.
//
// The mesh is a closed polygonal surface: one face per collocation point (tread cells are quads
// in (ψ, y), sidewall cells annular sectors), vertices shared, with every rim and ring vertex
// inserted into the faces on both sides, so every edge is shared by exactly two faces with
// opposite directions (watertight, consistently oriented). Each collocation point's normal and
// area are its face's vector area ½Σ vᵢ × vᵢ₊₁ (exact for any closed polygon, planar or not),
// so Σ n ΔS over the closed mesh vanishes to rounding; its position is on the surface at the
// cell's middle (ψ, y).
//
// Equivalent sources sit a short depth inside the surface, along the inward normal: about one
// to two point spacings, the usual choice that keeps the least-squares problem well
// conditioned while the sources still resolve the surface's detail. Points, normals and sources
// are mirror-symmetric about the centre plane y = 0 for every spec (an odd `across` puts a
// tread row on the plane, mapped to itself) and about the plane x = 0 through the axle (the
// patch is centred under it; the sources are chosen by x-mirror pairs of cells), so the
// equivalent-source solve splits into four quarter-size problems (symmetry_basis.hpp).
// source_normals holds each source's cell normal, for combined sources (equivalent_sources.hpp).
//
// Graded tread (contact_refinement > 1). The horn between tread and road is a wedge a few mm
// high near where the tread leaves the road: a uniform 2 cm mesh does not see it, and a source
// in it is amplified only by a few dB instead of the 10–20 dB reported (Kropp, Becot &
// Barrelet, Acustica 86, 2000; Graf, Kuo & Dowling, JSV 256, 2002). The tread cells are then
// spacing/refinement wide where the tread meets the road and grow geometrically by
// `contact_growth` per cell away from it up to the uniform spacing 2πR/around: undeformed,
// from the bottom line both ways; deformed, from both patch edges both ways (into the patch and
// round the tyre). The sources keep the depth rule locally: 1.5 of the larger of the tread cell's
// sides (around and across), at most the uniform depth; near the contact they sit about 1.5
// row spacings (17 mm with 16 rows) inside the tread, above the road.
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rollnoise {

enum class TyreGeometry { undeformed, deformed };

// The loaded tyre's shape (geometry = deformed): the contact solution's mean patch and
// indentation, and the belt's parameters along the circumference that shape it beyond the patch.
// The defaults are the 205/55 R16 demo tyre at the CPX load (plate_rough_80kmh: patch 0.119 m ×
// 0.14 m, indentation 14.9 mm).
struct TyreDeformation {
  double patch_length = 0.119;        // 2a, m, along the road
  double patch_width = 0.14;          // w_c, m, across (≤ b)
  double indentation = 0.0149;        // d, m: the axle's approach to the road
  double belt_tension = 6.0e4;        // Tx, N/m
  double belt_bending = 7.0;          // Bx, N·m
  double foundation_stiffness = 3.2e6;  // s_f, N/m³
  double shoulder_lift = 0.003;       // h, m: the rows at the sidewalls lifted off the road at
                                      // the patch centre (the crown's drop beyond the patch width)
};

struct TyreSurfaceMeshSpec {
  double radius = 0.316;      // R, m
  double width = 0.18;        // b, m
  double clearance = 0.002;   // c, m, between the tread and the road (lowest line, or the flat)
  TyreGeometry geometry = TyreGeometry::undeformed;
  TyreDeformation deformation;  // used when geometry = deformed
  // About 5 points per wavelength at 3 kHz (λ = 11 cm) on the tread and on the sidewalls,
  // whose area is larger than the tread's: coarser sidewalls were the largest error.
  int around = 96;            // tread collocation points around (2.1 cm apart)
  int across = 8;             // tread collocation points across (2.3 cm)
  int sidewall_rings = 12;    // rings of collocation points on each sidewall (2.6 cm)
  double source_depth = 0.0;  // m inside the surface at the uniform spacing; 0: 1.5 tread point
                              // spacings. Tread: at most 1.5 × the larger side of the cell.
  int source_stride = 2;      // one source per this many collocation points (chosen on the half
                              // y ≤ 0 and mirrored)
  // Graded tread: the cells where the tread meets the road are 2πR/(around·contact_refinement)
  // wide (1: uniform); the cells grow by contact_growth per cell away from them (1 < growth ≤ 2).
  double contact_refinement = 1.0;
  double contact_growth = 1.2;
  // Nested refinement along the tread: each cell of the partition above (uniform or graded)
  // split into this many equal cells (fewer where they would be finer than the partition's
  // finest, the contact refinement's), so the coarser mesh's cells are unions of this one's (the
  // radiation stage's finer meshes for its upper anchors, tyre_radiation.hpp). The sidewall rings
  // then have around·tread_split points on the circumference of the rim, and the uniform source
  // depth is that of the split spacing.
  int tread_split = 1;
};

// The surface of the (deformed or undeformed) tyre as a function of the material angle ψ and y.
class TyreSurfaceShape {
 public:
  explicit TyreSurfaceShape(const TyreSurfaceMeshSpec& spec);

  double axle_height() const noexcept { return axle_; }
  // Half the patch in material angle (a/R; 0 undeformed), and its half-width (m; 0 undeformed).
  double patch_half_angle() const noexcept { return psi0_; }
  double patch_half_width() const noexcept { return half_width_; }
  // The polar angle round the axle (from the bottom, towards +x) of the material angle ψ
  // (continuous and increasing over all ψ), and its inverse.
  double polar_angle(double psi) const;
  double material_angle(double polar) const;
  // The distance from the axle of the surface at (ψ, y), |y| ≤ b/2.
  double radius(double psi, double y) const;
  Eigen::Vector3d position(double psi, double y) const;
  // The outward unit normal and the area element |∂P/∂ψ × ∂P/∂y| (m²/rad/m) at (ψ, y).
  Eigen::Vector3d normal(double psi, double y) const;
  double area_element(double psi, double y) const;
  // The enclosed volume by quadrature of the rows' cross-sections (independent of any mesh).
  double volume(int samples_around = 20000, int samples_across = 400) const;
  // The lowest height of the centre row above the road outside the flat (the deformed shape
  // must not dip into it): min z − c over ψ outside the patch. 0 undeformed.
  double lowest_gap_outside_patch() const;

 private:
  double deflection(double psi) const;  // R − r at the centre row
  double shoulder(double y) const;      // Δ(y)/d factor (0 within the patch width)
  Eigen::Matrix<double, 3, 2> tangents(double psi, double y) const;

  double radius_ = 0, width_ = 0, clearance_ = 0, axle_ = 0;
  bool deformed_ = false;
  double depth_ = 0;        // d
  double psi0_ = 0;         // a/R
  double phi0_ = 0;         // atan(a/(R − d))
  double half_width_ = 0;   // w_c/2
  double lift_ = 0;         // h
  // Beyond the patch, w(σ) = e^{−ασ}(A cos βσ + B sin βσ) (β > 0: complex roots) or
  // A e^{−k₂σ} + B e^{−k₁σ} (real roots), minus a small quadratic that makes w' = 0 at the top.
  bool oscillating_ = false;
  double k1_ = 0, k2_ = 0, alpha_ = 0, beta_ = 0, a_coef_ = 0, b_coef_ = 0, top_fix_ = 0, sigma_top_ = 0;
  double w_raw(double sigma) const;
  double w_raw_slope(double sigma) const;
};

struct TyreSurfaceMesh {
  Eigen::Matrix3Xd points;   // collocation points, m
  Eigen::Matrix3Xd normals;  // outward unit normals
  Eigen::VectorXd areas;     // surface element of each point, m²
  Eigen::Matrix3Xd sources;  // equivalent source positions, m
  Eigen::Matrix3Xd source_normals;  // the outward normal of the collocation point each source is under
  int tread_points = 0;      // the first tread_points columns are the tread band, index a + Na·b
  int tread_around = 0;      // Na
  int tread_across = 0;      // Nb
  // The tread cells' material-angle edges, rad from the bottom towards +x (the belt's arc
  // position over R): cell a spans [edges[a], edges[a + 1]] (Na + 1 values, edges[Na] =
  // edges[0] + 2π); its point is at the middle. Uniform mesh: edges[a] = (a − ½)·2π/Na.
  // Deformed: edges[0] is the patch's trailing edge −a/R.
  std::vector<double> tread_angle_edges;
  // The tread rows' edges across, y in m from −b/2 to b/2 (Nb + 1 values): row c spans
  // [row_edges[c], row_edges[c + 1]]. Deformed, the patch's sides ±w_c/2 are row edges when the
  // mesh has rows to spare for the shoulders.
  std::vector<double> tread_row_edges;
  double axle_height = 0.0;  // m above the road
  // The flat (deformed): tread cells a in [0, patch_cells) and rows in [flat_row_begin,
  // flat_row_end) lie on the road, at the clearance. Undeformed: 0 cells.
  int patch_cells = 0;
  int flat_row_begin = 0, flat_row_end = 0;
  // The closed polygonal surface: vertices, and one face per collocation point (face i is the
  // cell of point i), each a vertex loop ordered anticlockwise seen from outside.
  Eigen::Matrix3Xd vertices;
  std::vector<std::vector<int>> faces;
};

TyreSurfaceMesh make_tyre_surface_mesh(const TyreSurfaceMeshSpec& spec);

}  // namespace rollnoise
