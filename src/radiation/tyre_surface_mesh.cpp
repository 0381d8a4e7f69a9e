#include "radiation/tyre_surface_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rollnoise {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * kPi;

// The tread cells' widths in angle of the undeformed mesh, from the bottom cell (centred on
// φ = 0) round to +x and back from −x: uniform, or graded geometrically from the bottom
// (tyre_surface_mesh.hpp).
std::vector<double> undeformed_widths(const TyreSurfaceMeshSpec& s) {
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

// An interval of `length` cut into cells `fine` wide at both ends, growing by `growth` per cell
// towards the middle up to `coarse`, near-uniform cells in the middle (their count changed by
// `middle_delta` when ≥ 1 remain). Symmetric.
std::vector<double> graded_partition(double length, double fine, double growth, double coarse, int middle_delta,
                                     int* middle_count = nullptr) {
  std::vector<double> side;
  double used = 0.0;
  for (double w = fine;; w = std::min(w * growth, coarse)) {
    if (2.0 * (used + w) > length) break;
    side.push_back(w);
    used += w;
    if (w >= coarse) break;
  }
  const double rest = length - 2.0 * used;
  const double next = side.empty() ? fine : std::min(side.back() * growth, coarse);
  int middle = static_cast<int>(std::lround(rest / next));
  if (side.empty()) middle = std::max(middle, 1);
  if (middle >= 1) middle = std::max(1, middle + middle_delta);
  if (middle_count) *middle_count = middle;
  std::vector<double> out;
  if (middle == 0) {
    for (double& w : side) w *= length / (2.0 * used);
    out = side;
  } else {
    out = side;
    out.insert(out.end(), static_cast<std::size_t>(middle), rest / middle);
  }
  out.insert(out.end(), side.rbegin(), side.rend());
  return out;
}

Eigen::Vector3d vector_area(const Eigen::Matrix3Xd& vertices, const std::vector<int>& face) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const std::size_t n = face.size();
  for (std::size_t i = 0; i < n; ++i)
    sum += vertices.col(face[i]).cross(vertices.col(face[(i + 1) % n]));
  return 0.5 * sum;
}

}  // namespace

TyreSurfaceShape::TyreSurfaceShape(const TyreSurfaceMeshSpec& s)
    : radius_(s.radius), width_(s.width), clearance_(s.clearance), deformed_(s.geometry == TyreGeometry::deformed) {
  axle_ = radius_ + clearance_;
  if (!deformed_) return;
  const TyreDeformation& d = s.deformation;
  const double half_length = 0.5 * d.patch_length;
  if (!(d.indentation > 0.0 && d.indentation < 0.5 * radius_) || !(half_length > 0.0 && half_length < 0.5 * radius_) ||
      !(d.patch_width > 0.0 && d.patch_width <= width_ + 1e-12) || !(d.shoulder_lift >= 0.0) ||
      !(d.belt_bending > 0.0 && d.belt_tension >= 0.0 && d.foundation_stiffness > 0.0))
    throw std::invalid_argument(
        "tyre surface mesh: the deformed tyre needs an indentation and a patch half-length within (0, R/2), a patch "
        "width within (0, b], a shoulder lift ≥ 0, bending and foundation stiffness > 0 and tension ≥ 0");
  depth_ = d.indentation;
  axle_ = radius_ - depth_ + clearance_;
  psi0_ = half_length / radius_;
  phi0_ = std::atan(half_length / (radius_ - depth_));
  half_width_ = 0.5 * std::min(d.patch_width, width_);
  lift_ = d.shoulder_lift;
  // The belt beyond the patch: Bx k⁴ − Tx k² + s_f = 0 for w ∝ e^{−kσ}.
  const double b = d.belt_bending, t = d.belt_tension, f = d.foundation_stiffness;
  const double disc = t * t - 4.0 * b * f;
  const double edge_radius = std::hypot(radius_ - depth_, half_length);
  const double w0 = radius_ - edge_radius;
  // The slope the flat leaves with (in σ = R(ψ − ψ0)): tangent continuity at the edge.
  const double stretch = (kPi - phi0_) / (radius_ * (kPi - psi0_));  // dφ/dσ
  const double w0_slope = -edge_radius * std::tan(phi0_) * stretch;
  if (disc > 1e-9 * t * t) {
    const double root = std::sqrt(disc);
    k1_ = std::sqrt((t + root) / (2.0 * b));
    k2_ = std::sqrt((t - root) / (2.0 * b));
    b_coef_ = (-w0_slope - k2_ * w0) / (k1_ - k2_);
    a_coef_ = w0 - b_coef_;
  } else {
    oscillating_ = true;
    const std::complex<double> k = std::sqrt(std::complex<double>(t, std::sqrt(std::max(0.0, -disc)) + 1e-12 * t) / (2.0 * b));
    alpha_ = std::abs(k.real());
    beta_ = std::abs(k.imag());
    a_coef_ = w0;
    b_coef_ = (w0_slope + alpha_ * w0) / beta_;
  }
  sigma_top_ = radius_ * (kPi - psi0_);
  top_fix_ = w_raw_slope(sigma_top_);
}

double TyreSurfaceShape::w_raw(double sigma) const {
  if (oscillating_) return std::exp(-alpha_ * sigma) * (a_coef_ * std::cos(beta_ * sigma) + b_coef_ * std::sin(beta_ * sigma));
  return a_coef_ * std::exp(-k2_ * sigma) + b_coef_ * std::exp(-k1_ * sigma);
}

double TyreSurfaceShape::w_raw_slope(double sigma) const {
  if (oscillating_)
    return std::exp(-alpha_ * sigma) * ((-alpha_ * a_coef_ + beta_ * b_coef_) * std::cos(beta_ * sigma) +
                                        (-alpha_ * b_coef_ - beta_ * a_coef_) * std::sin(beta_ * sigma));
  return -k2_ * a_coef_ * std::exp(-k2_ * sigma) - k1_ * b_coef_ * std::exp(-k1_ * sigma);
}

double TyreSurfaceShape::deflection(double psi) const {
  if (!deformed_) return 0.0;
  const double p = std::abs(std::remainder(psi, kTwoPi));
  if (p <= psi0_) return radius_ - std::hypot(radius_ - depth_, radius_ * p);
  const double sigma = radius_ * (p - psi0_);
  // Minus a quadratic with zero value and slope at the edge that makes the slope vanish at the
  // top (a few 10⁻⁵ m): the two sides then meet there without a kink.
  return w_raw(sigma) - top_fix_ * sigma * sigma / (2.0 * sigma_top_);
}

double TyreSurfaceShape::shoulder(double y) const {
  if (!deformed_ || lift_ == 0.0) return 0.0;
  const double beyond = std::abs(y) - half_width_;
  const double span = 0.5 * width_ - half_width_;
  if (beyond <= 0.0 || span <= 0.0) return 0.0;
  const double u = std::min(1.0, beyond / span);
  return lift_ * u * u / depth_;
}

double TyreSurfaceShape::polar_angle(double psi) const {
  if (!deformed_) return psi;
  const double turns = std::round(psi / kTwoPi);
  const double local = psi - kTwoPi * turns;
  const double p = std::abs(local);
  const double phi = p <= psi0_ ? std::atan(radius_ * p / (radius_ - depth_))
                                : phi0_ + (p - psi0_) * (kPi - phi0_) / (kPi - psi0_);
  return std::copysign(phi, local) + kTwoPi * turns;
}

double TyreSurfaceShape::material_angle(double polar) const {
  if (!deformed_) return polar;
  const double turns = std::round(polar / kTwoPi);
  const double local = polar - kTwoPi * turns;
  const double p = std::abs(local);
  const double psi = p <= phi0_ ? (radius_ - depth_) * std::tan(p) / radius_
                                : psi0_ + (p - phi0_) * (kPi - psi0_) / (kPi - phi0_);
  return std::copysign(psi, local) + kTwoPi * turns;
}

double TyreSurfaceShape::radius(double psi, double y) const {
  return radius_ - deflection(psi) * (1.0 + shoulder(y));
}

Eigen::Vector3d TyreSurfaceShape::position(double psi, double y) const {
  const double phi = polar_angle(psi);
  const double r = radius(psi, y);
  return {r * std::sin(phi), y, axle_ - r * std::cos(phi)};
}

Eigen::Matrix<double, 3, 2> TyreSurfaceShape::tangents(double psi, double y) const {
  const double h = 1e-6;
  const double hy = 1e-6 * width_;
  const double y0 = std::max(-0.5 * width_, y - hy), y1 = std::min(0.5 * width_, y + hy);
  Eigen::Matrix<double, 3, 2> t;
  t.col(0) = (position(psi + h, y) - position(psi - h, y)) / (2.0 * h);
  t.col(1) = (position(psi, y1) - position(psi, y0)) / (y1 - y0);
  return t;
}

Eigen::Vector3d TyreSurfaceShape::normal(double psi, double y) const {
  const Eigen::Matrix<double, 3, 2> t = tangents(psi, y);
  return t.col(1).cross(t.col(0)).normalized();  // ŷ × x̂ = −ẑ at the bottom: outward
}

double TyreSurfaceShape::area_element(double psi, double y) const {
  const Eigen::Matrix<double, 3, 2> t = tangents(psi, y);
  return t.col(1).cross(t.col(0)).norm();
}

double TyreSurfaceShape::volume(int samples_around, int samples_across) const {
  // Each row's cross-section ½∮ r² dφ, by the midpoint rule in ψ on the flat and beyond it
  // (dφ/dψ is smooth on each), then the midpoint rule across.
  const auto section = [&](double y) {
    double sum = 0.0;
    const int n_flat = deformed_ ? std::max(2, samples_around / 10) : 0;
    const int n_out = samples_around - n_flat;
    if (n_flat > 0) {
      const double h = 2.0 * psi0_ / n_flat;
      for (int i = 0; i < n_flat; ++i) {
        const double psi = -psi0_ + (i + 0.5) * h;
        const double r = radius(psi, y);
        const double dphi = radius_ * (radius_ - depth_) / ((radius_ - depth_) * (radius_ - depth_) + radius_ * radius_ * psi * psi);
        sum += 0.5 * r * r * dphi * h;
      }
    }
    const double h = (kTwoPi - 2.0 * psi0_) / n_out;
    const double dphi = deformed_ ? (kPi - phi0_) / (kPi - psi0_) : 1.0;
    for (int i = 0; i < n_out; ++i) {
      const double psi = psi0_ + (i + 0.5) * h;
      const double r = radius(psi, y);
      sum += 0.5 * r * r * dphi * h;
    }
    return sum;
  };
  double v = 0.0;
  const double hy = width_ / samples_across;
  for (int j = 0; j < samples_across; ++j) v += section(-0.5 * width_ + (j + 0.5) * hy) * hy;
  return v;
}

double TyreSurfaceShape::lowest_gap_outside_patch() const {
  if (!deformed_) return 0.0;
  double lowest = std::numeric_limits<double>::infinity();
  for (int i = 1; i <= 20000; ++i) {
    const double psi = psi0_ + (kPi - psi0_) * i / 20000.0;
    lowest = std::min(lowest, position(psi, 0.0).z() - clearance_);
  }
  return lowest;
}

TyreSurfaceMesh make_tyre_surface_mesh(const TyreSurfaceMeshSpec& s) {
  if (!(s.radius > 0 && s.width > 0 && s.clearance > 0) || s.around < 8 || s.across < 1 || s.sidewall_rings < 1 ||
      !(s.source_depth >= 0 && s.source_depth < 0.5 * s.width) || s.source_stride < 1 || s.tread_split < 1 ||
      s.tread_split > 64)
    throw std::invalid_argument("tyre surface mesh: sizes must be positive (clearance > 0, source depth below half the width)");
  if (!(s.contact_refinement >= 1.0 && s.contact_refinement <= 1000.0) || !(s.contact_growth > 1.0 && s.contact_growth <= 2.0))
    throw std::invalid_argument("tyre surface mesh: contact refinement must be within 1 ... 1000, growth within (1, 2]");
  const TyreSurfaceShape shape(s);
  const bool deformed = s.geometry == TyreGeometry::deformed;
  if (deformed && shape.lowest_gap_outside_patch() < -1e-12)
    throw std::invalid_argument("tyre surface mesh: the deformed tread dips below the road beyond the patch");
  TyreSurfaceMesh mesh;
  mesh.axle_height = shape.axle_height();

  // Tread cells around, in material angle.
  const double dphi = kTwoPi / s.around;
  const int split = s.tread_split;
  // At the uniform spacing (split).
  const double depth = s.source_depth > 0.0 ? s.source_depth : 1.5 * s.radius * dphi / split;
  std::vector<double> widths;
  double start = 0.0;
  if (!deformed) {
    widths = undeformed_widths(s);
    start = -0.5 * widths[0];
  } else {
    // Fine cells at both patch edges, growing into the patch and round the tyre.
    const double fine = dphi / s.contact_refinement;
    const double psi0 = shape.patch_half_angle();
    const std::vector<double> patch = graded_partition(2.0 * psi0, fine, s.contact_growth, dphi, 0);
    int middle = 0;
    std::vector<double> outside = graded_partition(kTwoPi - 2.0 * psi0, fine, s.contact_growth, dphi, 0, &middle);
    // As many as make Na a multiple of the source stride, when the middle allows.
    const auto total = [&] { return static_cast<int>(patch.size() + outside.size()); };
    for (int step = 1; step < s.source_stride && total() % s.source_stride != 0 && middle >= 1; ++step) {
      const int up = step, down = -step;
      for (int delta : {up, down}) {
        if (middle + delta < 1) continue;
        const std::vector<double> trial = graded_partition(kTwoPi - 2.0 * psi0, fine, s.contact_growth, dphi, delta);
        if (static_cast<int>(patch.size() + trial.size()) % s.source_stride == 0) {
          outside = trial;
          break;
        }
      }
    }
    widths = patch;
    widths.insert(widths.end(), outside.begin(), outside.end());
    start = -psi0;
    mesh.patch_cells = static_cast<int>(patch.size());
  }
  if (split > 1) {
    // Each cell in `split` equal parts, but none finer than the finest cell of the unsplit
    // partition (the contact refinement's): the graded cells at the contact keep their size, so
    // the sources under them stay about as far apart as they are deep (halving them put the
    // sources 8 spacings deep there and the system's condition number near 1e7).
    const double finest = dphi / std::max(s.contact_refinement, static_cast<double>(split));
    std::vector<double> whole = std::move(widths);
    widths.clear();
    int patch = 0;
    for (std::size_t a = 0; a < whole.size(); ++a) {
      const int parts = std::min(split, std::max(1, static_cast<int>(std::floor(whole[a] / finest + 1e-9))));
      widths.insert(widths.end(), static_cast<std::size_t>(parts), whole[a] / parts);
      if (static_cast<int>(a) < mesh.patch_cells) patch += parts;
    }
    mesh.patch_cells = patch;
  }
  const auto around = static_cast<int>(widths.size());
  std::vector<double> edges(widths.size() + 1);
  edges[0] = start;
  for (std::size_t a = 0; a < widths.size(); ++a) edges[a + 1] = edges[a] + widths[a];
  edges.back() = edges.front() + kTwoPi;

  // Rows across, mirror-symmetric: deformed, the patch's sides are row edges when the shoulders
  // can have rows of their own.
  std::vector<double> rows(static_cast<std::size_t>(s.across) + 1);
  {
    const double b = s.width;
    const double dy = b / s.across;
    int shoulder_rows = 0;
    const double shoulder = 0.5 * b - shape.patch_half_width();
    if (deformed && shoulder > 1e-9 * b) {
      shoulder_rows = static_cast<int>(std::lround(shoulder / dy));
      if (shoulder_rows == 0 && s.across >= 3) shoulder_rows = 1;
      shoulder_rows = std::min(shoulder_rows, (s.across - 1) / 2);
    }
    const int flat_rows = s.across - 2 * shoulder_rows;
    for (int c = 0; 2 * c <= s.across; ++c) {
      double y = 0.0;
      if (shoulder_rows == 0)
        y = -0.5 * b + c * dy;
      else if (c <= shoulder_rows)
        y = -0.5 * b + c * shoulder / shoulder_rows;
      else
        y = -shape.patch_half_width() + (c - shoulder_rows) * 2.0 * shape.patch_half_width() / flat_rows;
      rows[static_cast<std::size_t>(c)] = y;
      rows[static_cast<std::size_t>(s.across - c)] = -y;
    }
    if (s.across % 2 == 0) rows[static_cast<std::size_t>(s.across / 2)] = 0.0;
    if (deformed) {
      if (shoulder_rows > 0 || shoulder <= 1e-9 * b) {
        mesh.flat_row_begin = shoulder_rows;
        mesh.flat_row_end = s.across - shoulder_rows;
      } else {  // no rows to spare: the rows whose middle is on the flat
        for (int c = 0; c < s.across; ++c) {
          const double mid = 0.5 * (rows[static_cast<std::size_t>(c)] + rows[static_cast<std::size_t>(c) + 1]);
          if (std::abs(mid) <= shape.patch_half_width()) {
            if (mesh.flat_row_end == 0) mesh.flat_row_begin = c;
            mesh.flat_row_end = c + 1;
          }
        }
      }
    }
  }

  // Vertices: the tread grid (a + Na·c, c = 0 … Nb), then per sidewall the extra rim vertices,
  // the inner circles' vertices and the centre.
  std::vector<Eigen::Vector3d> vertices;
  for (int c = 0; c <= s.across; ++c)
    for (int a = 0; a < around; ++a)
      vertices.push_back(shape.position(edges[static_cast<std::size_t>(a)], rows[static_cast<std::size_t>(c)]));
  const auto tread_vertex = [&](int a, int c) { return ((a % around) + around) % around + around * c; };

  struct CircleVertex {
    double angle;  // polar, [0, 2π)
    int index;
    bool tread;
  };
  const auto wrap = [](double angle) {
    double t = std::fmod(angle, kTwoPi);
    if (t < 0) t += kTwoPi;
    return t;
  };
  const int rings = s.sidewall_rings;
  std::vector<int> ring_count(static_cast<std::size_t>(rings));
  for (int k = 0; k < rings; ++k) {
    const double r = s.radius * (k + 0.5) / rings;
    ring_count[static_cast<std::size_t>(k)] = std::max(6, static_cast<int>(std::lround(s.around * split * r / s.radius)));
  }
  const auto divisions = [&](int k) {
    std::vector<double> out;
    const int n = ring_count[static_cast<std::size_t>(k)];
    for (int m = 0; m < n; ++m) out.push_back(wrap(kTwoPi * (m + 0.5 * (k % 2) - 0.5) / n));
    return out;
  };
  const double axle = shape.axle_height();
  // The rim of a sidewall at the polar angle θ, and a point of the disk scaled from it.
  const auto disk_point = [&](double theta, double fraction, double y) {
    const Eigen::Vector3d rim = shape.position(shape.material_angle(theta), y);
    return Eigen::Vector3d(fraction * rim.x(), y, axle + fraction * (rim.z() - axle));
  };
  // circles[side][j], j = 1 … rings (rings: the rim), sorted by angle; centre[side].
  std::vector<std::vector<std::vector<CircleVertex>>> circles(2, std::vector<std::vector<CircleVertex>>(static_cast<std::size_t>(rings) + 1));
  int centre[2] = {0, 0};
  const double angle_tolerance = 1e-12;
  for (int side = 0; side < 2; ++side) {
    const double y = side == 0 ? -0.5 * s.width : 0.5 * s.width;
    const int row = side == 0 ? 0 : s.across;
    for (int j = 1; j <= rings; ++j) {
      std::vector<CircleVertex>& circle = circles[static_cast<std::size_t>(side)][static_cast<std::size_t>(j)];
      std::vector<double> angles = divisions(j - 1);
      if (j < rings) {
        const std::vector<double> inner = divisions(j);
        angles.insert(angles.end(), inner.begin(), inner.end());
      } else {
        for (int a = 0; a < around; ++a)
          circle.push_back({wrap(shape.polar_angle(edges[static_cast<std::size_t>(a)])), tread_vertex(a, row), true});
      }
      for (double t : angles) {
        bool known = false;
        for (const CircleVertex& v : circle)
          if (std::abs(std::remainder(v.angle - t, kTwoPi)) < angle_tolerance) known = true;
        if (known) continue;
        vertices.push_back(disk_point(t, static_cast<double>(j) / rings, y));
        circle.push_back({t, static_cast<int>(vertices.size()) - 1, false});
      }
      std::sort(circle.begin(), circle.end(), [](const CircleVertex& p, const CircleVertex& q) { return p.angle < q.angle; });
    }
    vertices.emplace_back(0.0, y, axle);
    centre[side] = static_cast<int>(vertices.size()) - 1;
  }
  mesh.vertices.resize(3, static_cast<Eigen::Index>(vertices.size()));
  for (std::size_t i = 0; i < vertices.size(); ++i) mesh.vertices.col(static_cast<Eigen::Index>(i)) = vertices[i];
  // The vertices of a circle within [lo, hi] (angles continued round the turn), by angle.
  const auto within = [&](const std::vector<CircleVertex>& circle, double lo, double hi, bool open, bool rim_extras_only) {
    std::vector<std::pair<double, int>> out;
    const double mid = 0.5 * (lo + hi);
    const double tol = open ? -angle_tolerance : angle_tolerance;
    for (const CircleVertex& v : circle) {
      if (rim_extras_only && v.tread) continue;
      const double t = v.angle + kTwoPi * std::round((mid - v.angle) / kTwoPi);
      if (t >= lo - tol && t <= hi + tol) out.emplace_back(t, v.index);
    }
    std::sort(out.begin(), out.end());
    std::vector<int> indices;
    for (const auto& p : out) indices.push_back(p.second);
    return indices;
  };

  // Faces and collocation points: the tread cells, then the sidewall cells.
  std::vector<Eigen::Vector3d> points;
  std::vector<double> depths;
  const auto orient = [&](std::vector<int>& face, const Eigen::Vector3d& outward) {
    if (vector_area(mesh.vertices, face).dot(outward) < 0.0) std::reverse(face.begin(), face.end());
  };
  for (int c = 0; c < s.across; ++c) {
    const double y0 = rows[static_cast<std::size_t>(c)], y1 = rows[static_cast<std::size_t>(c) + 1];
    for (int a = 0; a < around; ++a) {
      const double psi0 = edges[static_cast<std::size_t>(a)], psi1 = edges[static_cast<std::size_t>(a) + 1];
      const double lo = shape.polar_angle(psi0), hi = shape.polar_angle(psi1);
      std::vector<int> face{tread_vertex(a, c)};
      if (c == 0)
        for (int v : within(circles[0][static_cast<std::size_t>(rings)], lo, hi, true, true)) face.push_back(v);
      face.push_back(tread_vertex(a + 1, c));
      face.push_back(tread_vertex(a + 1, c + 1));
      if (c + 1 == s.across) {
        std::vector<int> extras = within(circles[1][static_cast<std::size_t>(rings)], lo, hi, true, true);
        face.insert(face.end(), extras.rbegin(), extras.rend());
      }
      face.push_back(tread_vertex(a, c + 1));
      const double psi = 0.5 * (psi0 + psi1), y = 0.5 * (y0 + y1);
      orient(face, shape.normal(psi, y));
      mesh.faces.push_back(std::move(face));
      points.push_back(shape.position(psi, y));
      // 1.5 local spacings inside, the larger of the cell's two sides (along and across),
      // at most the uniform mesh's depth: a source much shallower than the row spacing makes a
      // velocity spot that the rows do not resolve (measured: the field of a monopole 1 cm
      // inside the tread above the patch edge was 16 % off at 1 kHz with the depth set by the
      // 2 mm cells along alone, 0.2 % with this rule).
      depths.push_back(std::min(depth, 1.5 * std::max(s.radius * (psi1 - psi0), y1 - y0)));
    }
  }
  const int tread = static_cast<int>(points.size());
  for (int side = 0; side < 2; ++side) {
    const double y = side == 0 ? -0.5 * s.width : 0.5 * s.width;
    for (int k = 0; k < rings; ++k) {
      const int n = ring_count[static_cast<std::size_t>(k)];
      for (int m = 0; m < n; ++m) {
        const double theta = kTwoPi * (m + 0.5 * (k % 2)) / n;
        const double lo = theta - kPi / n, hi = theta + kPi / n;
        std::vector<int> face = within(circles[static_cast<std::size_t>(side)][static_cast<std::size_t>(k) + 1], lo, hi, false, false);
        if (k == 0) {
          face.push_back(centre[side]);
        } else {
          const std::vector<int> inner = within(circles[static_cast<std::size_t>(side)][static_cast<std::size_t>(k)], lo, hi, false, false);
          face.insert(face.end(), inner.rbegin(), inner.rend());
        }
        orient(face, Eigen::Vector3d(0.0, y, 0.0));
        mesh.faces.push_back(std::move(face));
        points.push_back(disk_point(theta, (k + 0.5) / rings, y));
        depths.push_back(depth);
      }
    }
  }

  const auto n = static_cast<Eigen::Index>(points.size());
  mesh.points.resize(3, n);
  mesh.normals.resize(3, n);
  mesh.areas.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d area = vector_area(mesh.vertices, mesh.faces[static_cast<std::size_t>(i)]);
    mesh.points.col(i) = points[static_cast<std::size_t>(i)];
    mesh.areas(i) = area.norm();
    mesh.normals.col(i) = area / area.norm();
  }
  mesh.tread_points = tread;
  mesh.tread_around = around;
  mesh.tread_across = s.across;
  mesh.tread_angle_edges = std::move(edges);
  mesh.tread_row_edges = std::move(rows);
  // Sources: every stride-th collocation point of one quarter of the tyre (y ≤ 0, and the half
  // of each x-mirrored pair of cells that comes first), and the mirror images of those, so that
  // the sources are symmetric like the points under y → −y and x → −x and the solve splits
  // (symmetry_basis.hpp). Tread row c mirrors row Nb − 1 − c (same angles), the +y sidewall the
  // −y one point by point; along the tread, cell a mirrors the cell whose middle is at −ψ(a),
  // on a ring point m the point at the opposite angle. A point is chosen when the first of its
  // x-mirror pair is the stride-th; where the pair's two members have the same parity (the
  // undeformed tread with Na even, the deformed one with an odd count of patch cells), these
  // are the stride-th points in global order. Each point moves inwards along its normal by its
  // depth.
  const int sidewall = static_cast<int>(n) - tread;  // both sidewalls
  std::vector<int> tread_mirror(static_cast<std::size_t>(around));
  for (int a = 0; a < around; ++a) {
    const std::vector<double>& e = mesh.tread_angle_edges;
    const double middle = 0.5 * (e[static_cast<std::size_t>(a)] + e[static_cast<std::size_t>(a) + 1]);
    tread_mirror[static_cast<std::size_t>(a)] = a;  // none found: the cell is its own
    for (int b = 0; b < around; ++b) {
      const double other = 0.5 * (e[static_cast<std::size_t>(b)] + e[static_cast<std::size_t>(b) + 1]);
      if (std::abs(std::remainder(middle + other, kTwoPi)) < 1e-9) tread_mirror[static_cast<std::size_t>(a)] = b;
    }
  }
  std::vector<int> ring_mirror;  // per sidewall point j (ring by ring): the point at the opposite angle
  for (int k = 0, offset = 0; k < rings; ++k) {
    const int count = ring_count[static_cast<std::size_t>(k)];
    for (int m = 0; m < count; ++m) ring_mirror.push_back(offset + (k % 2 == 0 ? (count - m) % count : count - 1 - m));
    offset += count;
  }
  std::vector<Eigen::Index> chosen;
  for (int c = 0; c < s.across; ++c) {
    const int lower = std::min(c, s.across - 1 - c);
    for (int a = 0; a < around; ++a) {
      const int first = std::min(a, tread_mirror[static_cast<std::size_t>(a)]);
      if ((first + around * lower) % s.source_stride == 0) chosen.push_back(a + around * c);
    }
  }
  for (int side = 0; side < 2; ++side)
    for (int j = 0; j < sidewall / 2; ++j) {
      const int first = std::min(j, ring_mirror[static_cast<std::size_t>(j)]);
      if ((tread + first) % s.source_stride == 0) chosen.push_back(tread + side * (sidewall / 2) + j);
    }
  mesh.sources.resize(3, static_cast<Eigen::Index>(chosen.size()));
  mesh.source_normals.resize(3, static_cast<Eigen::Index>(chosen.size()));
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const Eigen::Index p = chosen[i];
    mesh.sources.col(static_cast<Eigen::Index>(i)) = mesh.points.col(p) - depths[static_cast<std::size_t>(p)] * mesh.normals.col(p);
    mesh.source_normals.col(static_cast<Eigen::Index>(i)) = mesh.normals.col(p);
  }
  return mesh;
}

}  // namespace rollnoise
