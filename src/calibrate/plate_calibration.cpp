#include "calibrate/plate_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/error.hpp"

namespace rollnoise {
namespace {

// Parameter order of PlateCalibration::parameters().
enum Index : std::size_t {
  mass_per_area,
  tension_x,
  tension_y,
  bending_x,
  bending_y,
  bending_xy,
  foundation_stiffness,
  loss_factor,
  count
};

class PlateReceptance : public ReceptanceFunction {
 public:
  PlateReceptance(const PlateParameters& plate, const FrfPoints& points) {
    const KroppPlate geometry(plate);
    modal_area_ = geometry.circumference() * plate.width / 2.0;
    // Reduce to one turn first, as KroppPlate does, so cos(k_m·dx) keeps its digits.
    const double dx = std::remainder(points.response.x - points.excitation.x, geometry.circumference());
    const int modes_x = plate.circumferential_modes;
    for (int m = 0; m <= modes_x; ++m) {
      const double k = geometry.wavenumber_x(m);
      kx2_.push_back(k * k);
      kx4_.push_back(k * k * k * k);
      c_.push_back((m == 0 ? 1.0 : 2.0) * std::cos(k * dx));
    }
    for (int n = 1; n <= plate.lateral_modes; ++n) {
      const double k = geometry.wavenumber_y(n);
      const double s = std::sin(k * points.response.y) * std::sin(k * points.excitation.y);
      if (s == 0.0) continue;
      ky2_.push_back(k * k);
      ky4_.push_back(k * k * k * k);
      s_.push_back(s);
    }
  }

  std::complex<double> evaluate(std::span<const double> v, double omega, std::complex<double>* gradient,
                                std::span<const std::size_t> wanted) const override {
    const double mpa = v[mass_per_area];
    const double eta = v[loss_factor];
    const double omega2 = omega * omega;
    const double modal_mass = mpa * modal_area_;
    const bool derivatives = gradient != nullptr && !wanted.empty();
    // Sums over the modes, real and imaginary parts: α (A), and for the derivatives
    // Σ c s g (G0), Σ c s g k_m² (G2), Σ c s g k_m⁴ (G4), Σ c s g ω_mn² (W), Σ c s e ω_mn (H)
    // with e = 1/u², g = e·(1 + iωη/(2ω_mn)); the k_n powers multiply the lateral sums (Gy2,
    // Gy4, and Gxy for a_mn = 2 k_m² k_n²).
    double A[2] = {}, G0[2] = {}, G2[2] = {}, G4[2] = {}, W[2] = {}, H[2] = {}, Gy2[2] = {}, Gy4[2] = {}, Gxy[2] = {};
    for (std::size_t n = 0; n < s_.size(); ++n) {
      const double base = v[bending_y] * ky4_[n] + v[tension_y] * ky2_[n] + v[foundation_stiffness];
      const double per_kx2 = v[tension_x] + 2.0 * v[bending_xy] * ky2_[n];
      double a[2] = {}, g0[2] = {}, g2[2] = {}, g4[2] = {}, w[2] = {}, h[2] = {};
      for (std::size_t m = 0; m < c_.size(); ++m) {
        const double K = base + per_kx2 * kx2_[m] + v[bending_x] * kx4_[m];
        const double wn2 = K / mpa;
        const double wn = std::sqrt(wn2);
        const double ur = wn2 - omega2;
        const double ui = omega * eta * wn;
        const double norm = 1.0 / (ur * ur + ui * ui);
        const double ir = ur * norm;  // 1/u
        const double ii = -ui * norm;
        const double c = c_[m];
        a[0] += c * ir;
        a[1] += c * ii;
        if (!derivatives) continue;
        const double er = ir * ir - ii * ii;  // e = 1/u²
        const double ei = 2.0 * ir * ii;
        const double q = omega * eta / (2.0 * wn);
        const double gr = c * (er - ei * q);  // c·g
        const double gi = c * (ei + er * q);
        g0[0] += gr;
        g0[1] += gi;
        g2[0] += gr * kx2_[m];
        g2[1] += gi * kx2_[m];
        g4[0] += gr * kx4_[m];
        g4[1] += gi * kx4_[m];
        w[0] += gr * wn2;
        w[1] += gi * wn2;
        h[0] += c * er * wn;
        h[1] += c * ei * wn;
      }
      const double s = s_[n];
      for (int j = 0; j < 2; ++j) {
        A[j] += s * a[j];
        G0[j] += s * g0[j];
        G2[j] += s * g2[j];
        G4[j] += s * g4[j];
        W[j] += s * w[j];
        H[j] += s * h[j];
        Gy2[j] += s * ky2_[n] * g0[j];
        Gy4[j] += s * ky4_[n] * g0[j];
        Gxy[j] += s * 2.0 * ky2_[n] * g2[j];  // a_mn = 2 k_m² k_n²
      }
    }
    const std::complex<double> alpha(A[0] / modal_mass, A[1] / modal_mass);
    if (!derivatives) return alpha;
    const double stiffness_scale = -1.0 / (modal_mass * mpa);
    const auto sum = [](const double (&x)[2], double scale) { return std::complex<double>(x[0] * scale, x[1] * scale); };
    for (std::size_t k : wanted) {
      switch (k) {
        case mass_per_area:
          gradient[k] = -alpha / mpa + sum(W, 1.0 / (modal_mass * mpa));
          break;
        case tension_x:
          gradient[k] = sum(G2, stiffness_scale);
          break;
        case tension_y:
          gradient[k] = sum(Gy2, stiffness_scale);
          break;
        case bending_x:
          gradient[k] = sum(G4, stiffness_scale);
          break;
        case bending_y:
          gradient[k] = sum(Gy4, stiffness_scale);
          break;
        case bending_xy:
          gradient[k] = sum(Gxy, stiffness_scale);
          break;
        case foundation_stiffness:
          gradient[k] = sum(G0, stiffness_scale);
          break;
        case loss_factor:
          // −Σ c s iω ω_mn e / M
          gradient[k] = std::complex<double>(0.0, -omega) * sum(H, 1.0 / modal_mass);
          break;
        default:
          break;
      }
    }
    return alpha;
  }

 private:
  double modal_area_ = 0.0;  // L·b/2: the modal mass is m''·L·b/2
  std::vector<double> kx2_, kx4_, c_;
  std::vector<double> ky2_, ky4_, s_;  // lateral orders with s_n ≠ 0 only
};

}  // namespace

PlateCalibration::PlateCalibration(const PlateParameters& plate) : plate_(plate) {
  const KroppPlate check(plate_);  // validates
  parameters_.resize(count);
  parameters_[mass_per_area] = log_parameter("mass_per_area", "kg/m^2", plate.mass_per_area);
  parameters_[tension_x] = log_parameter("tension_x", "N/m", plate.tension_x);
  parameters_[tension_y] = log_parameter("tension_y", "N/m", plate.tension_y);
  parameters_[bending_x] = log_parameter("bending_x", "N*m", plate.bending_x);
  parameters_[bending_y] = log_parameter("bending_y", "N*m", plate.bending_y);
  parameters_[bending_xy] = log_parameter("bending_xy", "N*m", plate.bending_xy);
  parameters_[foundation_stiffness] = log_parameter("foundation_stiffness", "N/m^3", plate.foundation_stiffness);
  // η < 1: every mode stays well under-damped (ζ = η/2 < 0.5), as rubber-cord belts are.
  parameters_[loss_factor] = log_parameter("loss_factor", "1", plate.loss_factor, 0.0, 1.0);
}

std::vector<std::string> PlateCalibration::default_free_parameters() const {
  return {"tension_x", "bending_x", "foundation_stiffness", "loss_factor"};
}

std::unique_ptr<ReceptanceFunction> PlateCalibration::receptance(const FrfPoints& points) const {
  const double slack = 1e-9 * plate_.width;
  for (const BeltPosition* p : {&points.response, &points.excitation}) {
    if (!std::isfinite(p->x) || !(p->y >= -slack && p->y <= plate_.width + slack)) {
      std::ostringstream problem;
      problem << "the " << (p == &points.response ? "response" : "excitation") << " position (" << p->x << ", "
              << p->y << ") m is not on the belt: y must lie within [0, width = " << plate_.width
              << " m] (measured across the belt from one edge)";
      throw InputError("", "", problem.str());
    }
  }
  FrfPoints clamped = points;
  clamped.response.y = std::clamp(points.response.y, 0.0, plate_.width);
  clamped.excitation.y = std::clamp(points.excitation.y, 0.0, plate_.width);
  return std::make_unique<PlateReceptance>(plate_, clamped);
}

double PlateCalibration::highest_frequency_hz() const {
  const KroppPlate plate(plate_);
  const double stiffness = std::min(plate.modal_stiffness(plate_.circumferential_modes + 1, 1),
                                    plate.modal_stiffness(0, plate_.lateral_modes + 1));
  return 0.5 * std::sqrt(stiffness / plate_.mass_per_area) / (2.0 * std::numbers::pi);
}

PlateParameters PlateCalibration::with_values(std::span<const double> values) const {
  PlateParameters p = plate_;
  p.mass_per_area = values[mass_per_area];
  p.tension_x = values[tension_x];
  p.tension_y = values[tension_y];
  p.bending_x = values[bending_x];
  p.bending_y = values[bending_y];
  p.bending_xy = values[bending_xy];
  p.foundation_stiffness = values[foundation_stiffness];
  p.loss_factor = values[loss_factor];
  return p;
}

}  // namespace rollnoise
