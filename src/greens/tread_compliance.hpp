#pragma once
// Local (instantaneous) compliance of the tread between contact points: the contact
// compliance that a Kirchhoff plate lacks (MODEL.md §4, "Local deformation of the tread").
// Points sit at the centres of equal cells dx × dy; a force on a point acts as a uniform
// pressure F/(dx·dy) over its cell.
#include <Eigen/Core>

namespace rollnoise {

// Winkler bedding: independent springs, stiffness per area k_w (N/m³): C = I/(k_w·dx·dy).
Eigen::MatrixXd winkler_compliance(Eigen::Index points, double cell_dx, double cell_dy,
                                   double stiffness_per_area);

// Elastic half-space (Boussinesq/Love): C(p, q) = vertical surface displacement at point p from
// a unit force spread uniformly over the cell of point q (Love 1929). `positions` is P × 2
// (x, y) in m. E in Pa, ν in [0, 0.5] (rubber is nearly incompressible: ν ≈ 0.5).
Eigen::MatrixXd halfspace_compliance(const Eigen::MatrixX2d& positions, double cell_dx, double cell_dy,
                                     double youngs_modulus, double poisson_ratio);

// Love (1929): vertical surface displacement at (x, y) of an elastic half-space under a uniform
// pressure p = 1 Pa on the rectangle |x'| ≤ a, |y'| ≤ b (m per Pa).
double love_rectangle_displacement(double x, double y, double a, double b, double youngs_modulus,
                                   double poisson_ratio);

}  // namespace rollnoise
