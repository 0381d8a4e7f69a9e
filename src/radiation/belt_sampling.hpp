#pragma once
// From the belt's surface field to the radiating mesh: the response stage gives the radial
// velocity on the contact grid's fine cells (Nθ around × Ny across, 512 × 20 by default), the
// equivalent-source mesh has coarser tread cells (96 × 8). Each mesh cell takes the area-weighted
// mean of the belt cells it overlaps, so the volume velocity Σ v·ΔS of any pattern carries over
// exactly: at low frequency, where a tyre radiates as a monopole, that is what the sound depends
// on; finer detail than a mesh cell radiates inefficiently and would be lost by any sampling.
//
// Conventions: belt cell (j, g) is centred at the angle 2πg/Nθ from the bottom of the tyre, in
// the direction of travel, and at y_j = (j + ½)·b/Ny across the belt (SurfaceResponse); mesh tread
// cell a + Na·c spans the angles [edges[a], edges[a + 1]] of mesh.tread_angle_edges (uniform,
// or graded towards the contact; material angles, the belt's arc position over R, so the same
// belt cells land in the same cells whether the mesh is deformed or not) and the rows
// [row_edges[c], row_edges[c + 1]] of mesh.tread_row_edges (tyre_surface_mesh.hpp). Both bands
// span the same width b. On a deformed mesh a cell's area is that of the deformed surface: on the
// flat it equals the belt's (x = Rψ there); beyond it the cells are up to 2 % smaller than their
// material area (the radius drops by the deflection next to the patch), and the volume
// velocity the mesh carries is v·ΔS of the deformed cell.
#include <Eigen/SparseCore>

#include "radiation/tyre_surface_mesh.hpp"

namespace rollnoise {

// The sampling matrix (Na·Nb × Nθ·Ny) applied to the belt field flattened in column-major order
// of its Ny × Nθ matrix (index j + Ny·g). std::invalid_argument for counts < 1 or a mesh whose
// tread layout is inconsistent.
Eigen::SparseMatrix<double> belt_to_tread_matrix(int belt_around, int belt_across, const TyreSurfaceMesh& mesh);

// From one tread mesh to another with the same rows across (the radiation stage's meshes of one
// run, tyre_radiation.hpp): each cell of `to` takes the mean of the cells of `from` over its
// material angles, weighted by their overlap (Na_to·Nb × Na_from·Nb). When the cells of `to` are
// unions of those of `from` (TyreSurfaceMeshSpec::tread_split), belt → from → to equals
// belt → to: area-weighted means compose.
Eigen::SparseMatrix<double> tread_to_tread_matrix(const TyreSurfaceMesh& from, const TyreSurfaceMesh& to);

}  // namespace rollnoise
