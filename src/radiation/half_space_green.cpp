#include "radiation/half_space_green.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "radiation/equivalent_sources.hpp"
#include "radiation/impedance_plane_green.hpp"

namespace rollnoise {

using Complex = std::complex<double>;

ReflectionRegion reflection_region(const Eigen::Matrix3Xd& points, const Eigen::Matrix3Xd& sources) {
  if (points.cols() == 0 || sources.cols() == 0) throw std::invalid_argument("reflection region: no points or no sources");
  const Eigen::Vector3d lo_p = points.rowwise().minCoeff(), hi_p = points.rowwise().maxCoeff();
  const Eigen::Vector3d lo_s = sources.rowwise().minCoeff(), hi_s = sources.rowwise().maxCoeff();
  // The largest horizontal distance between the two boxes.
  const double dx = std::max(hi_p.x() - lo_s.x(), hi_s.x() - lo_p.x());
  const double dy = std::max(hi_p.y() - lo_s.y(), hi_s.y() - lo_p.y());
  ReflectionRegion out{std::hypot(dx, dy), lo_p.z() + lo_s.z(), hi_p.z() + hi_s.z()};
  if (!(out.z_min > 0.0)) throw std::invalid_argument("reflection region: every point must lie above the road (z > 0)");
  return out;
}

HalfSpaceGreen::HalfSpaceGreen(double k, std::complex<double> admittance, std::optional<ReflectionRegion> region,
                               std::size_t evaluations)
    : k_(k), admittance_(admittance) {
  if (!(k > 0.0) || !std::isfinite(k) || !std::isfinite(admittance.real()) || !std::isfinite(admittance.imag()) ||
      admittance.real() < 0.0)
    throw std::invalid_argument("half-space Green's function: k > 0 and a finite admittance with Re β >= 0 needed");
  if (region && !rigid() && evaluations > 0 &&
      ReflectedFieldTable::estimated_nodes(k, admittance, region->r_max, region->z_min, region->z_max) >= evaluations)
    region.reset();
  if (region && !rigid()) {
    const double spacing = ReflectedFieldTable::spacing_for(k, admittance, region->r_max, region->z_max);
    table_.emplace(k, admittance, region->r_max, region->z_min, region->z_max, spacing);
  }
}

ReflectedField HalfSpaceGreen::exact_correction(double r, double z, int derivatives) const {
  ReflectedField out{};
  if (rigid()) return out;
  const double radius = std::hypot(r, z);
  const double hz = 1e-4 * z, hr = 1e-4 * radius;
  const auto c = [&](double rr, double zz) { return impedance_plane_correction(k_, std::abs(rr), zz, admittance_); };
  out.value = c(r, z);
  if (derivatives == 0) return out;
  const Complex rp = c(r + hr, z), rm = c(r - hr, z), zp = c(r, z + hz), zm = c(r, z - hz);
  out.dr = (rp - rm) / (2.0 * hr);
  out.dz = (zp - zm) / (2.0 * hz);
  if (derivatives == 1) {
    out.dr_over_r = r > 0.0 ? out.dr / r : Complex(0.0);
    return out;
  }
  out.drr = (rp - 2.0 * out.value + rm) / (hr * hr);
  out.dzz = (zp - 2.0 * out.value + zm) / (hz * hz);
  out.drz = (c(r + hr, z + hz) - c(r + hr, z - hz) - c(r - hr, z + hz) + c(r - hr, z - hz)) / (4.0 * hr * hz);
  out.dr_over_r = r > 0.0 ? out.dr / r : out.drr;
  return out;
}

ReflectedField HalfSpaceGreen::correction(double r, double z, int derivatives) const {
  if (rigid()) return ReflectedField{};
  if (table_ && table_->covers(r, z)) return (*table_)(r, z, derivatives);
  return exact_correction(r, z, derivatives);
}

std::complex<double> HalfSpaceGreen::operator()(const Eigen::Vector3d& x, const Eigen::Vector3d& s) const {
  // The rigid road's direct wave and image (equivalent_sources.hpp).
  Complex g = helmholtz_green(x, s, k_, true);
  if (rigid()) return g;
  const double r = std::hypot(x.x() - s.x(), x.y() - s.y());
  // Only the value is needed: no differences.
  const double z = x.z() + s.z();
  if (table_ && table_->covers(r, z)) return g + (*table_)(r, z, 0).value;
  return g + impedance_plane_correction(k_, r, z, admittance_);
}

Eigen::Vector3cd HalfSpaceGreen::gradient(const Eigen::Vector3d& x, const Eigen::Vector3d& s) const {
  Eigen::Vector3cd g = helmholtz_green_gradient(x, s, k_, true);
  if (rigid()) return g;
  const double dx = x.x() - s.x(), dy = x.y() - s.y();
  const double r = std::hypot(dx, dy);
  const ReflectedField c = correction(r, x.z() + s.z(), 1);
  // ∇_x C = ∂C/∂r·(x_h − s_h)/r + ∂C/∂Z·ẑ.
  if (r > 0.0) {
    g.x() += c.dr * (dx / r);
    g.y() += c.dr * (dy / r);
  }
  g.z() += c.dz;
  return g;
}

}  // namespace rollnoise
