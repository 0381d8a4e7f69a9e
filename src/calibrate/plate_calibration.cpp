#include "calibrate/plate_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <mutex>
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

}  // namespace

// The modal frequencies ω_mn² and ω_mn of the last parameter values, shared by the receptances
// of all FRFs: every frequency line of every FRF needs them, and they change only when the fit
// moves the parameters. Guarded by a mutex, so receptances stay safe to evaluate in parallel.
struct PlateCalibration::ModeCache {
  std::mutex mutex;
  std::vector<double> key;   // the parameter values the table is for
  Eigen::ArrayXXd omega2;    // ω_mn², (M + 1) × N
  Eigen::ArrayXXd omega_n;   // ω_mn
};

namespace {

class PlateReceptance : public ReceptanceFunction {
 public:
  PlateReceptance(const PlateParameters& plate, const FrfPoints& points,
                  std::shared_ptr<PlateCalibration::ModeCache> cache)
      : cache_(std::move(cache)) {
    const KroppPlate geometry(plate);
    modal_area_ = geometry.circumference() * plate.width / 2.0;
    // Reduce to one turn first, as KroppPlate does, so cos(k_m·dx) keeps its digits.
    const double dx = std::remainder(points.response.x - points.excitation.x, geometry.circumference());
    const int columns = plate.circumferential_modes + 1;
    kx2_.resize(columns);
    kx4_.resize(columns);
    c_.resize(columns);
    for (int m = 0; m < columns; ++m) {
      const double k = geometry.wavenumber_x(m);
      kx2_[m] = k * k;
      kx4_[m] = k * k * k * k;
      c_[m] = (m == 0 ? 1.0 : 2.0) * std::cos(k * dx);
    }
    c_kx2_ = c_ * kx2_;
    c_kx4_ = c_ * kx4_;
    for (int n = 1; n <= plate.lateral_modes; ++n) {
      const double k = geometry.wavenumber_y(n);
      const double s = std::sin(k * points.response.y) * std::sin(k * points.excitation.y);
      if (s == 0.0) continue;  // a node line of the mode: it adds nothing
      lateral_.push_back(n - 1);
      ky2_.push_back(k * k);
      ky4_.push_back(k * k * k * k);
      s_.push_back(s);
    }
    plate_ = plate;
  }

  std::complex<double> evaluate(std::span<const double> v, double omega, std::complex<double>* gradient,
                                std::span<const std::size_t> wanted) const override {
    const double mpa = v[mass_per_area];
    const double eta = v[loss_factor];
    const double omega2 = omega * omega;
    const double modal_mass = mpa * modal_area_;
    const bool derivatives = gradient != nullptr && !wanted.empty();
    const std::lock_guard<std::mutex> lock(cache_->mutex);
    update_modes(v);
    // Sums over the modes, real and imaginary parts: α (A), and for the derivatives
    // Σ c s g (G0), Σ c s g k_m² (G2), Σ c s g k_m⁴ (G4), Σ c s g ω_mn² (W), Σ c s e ω_mn (H)
    // with e = 1/u², g = e·(1 + iωη/(2ω_mn)); the k_n powers multiply the lateral sums (Gy2,
    // Gy4, and Gxy for a_mn = 2 k_m² k_n²). Per lateral order the circumferential sums are
    // Eigen array expressions and dot products (vectorised).
    double A[2] = {}, G0[2] = {}, G2[2] = {}, G4[2] = {}, W[2] = {}, H[2] = {}, Gy2[2] = {}, Gy4[2] = {}, Gxy[2] = {};
    thread_local Eigen::ArrayXd ir, ii, er, ei, gr, gi, norm, q;
    // Only the sums the wanted derivatives need.
    bool need_w = false, need_h = false, need_g4 = false;
    if (derivatives)
      for (std::size_t k : wanted) {
        need_w = need_w || k == mass_per_area;
        need_h = need_h || k == loss_factor;
        need_g4 = need_g4 || k == bending_x;
      }
    for (std::size_t j = 0; j < s_.size(); ++j) {
      const auto wn2 = cache_->omega2.col(lateral_[j]);
      const auto wn = cache_->omega_n.col(lateral_[j]);
      // 1/u with u = ω_mn² − ω² + iωη·ω_mn.
      ir = wn2 - omega2;
      ii = (omega * eta) * wn;
      norm = (ir.square() + ii.square()).inverse();
      ir *= norm;
      ii *= -norm;
      const double s = s_[j];
      A[0] += s * (c_ * ir).sum();
      A[1] += s * (c_ * ii).sum();
      if (!derivatives) continue;
      er = ir.square() - ii.square();  // e = 1/u²
      ei = 2.0 * ir * ii;
      // g = e·(1 + iq), q = ωη/(2ω_mn)
      q = (0.5 * omega * eta) / wn;
      gr = er - ei * q;
      gi = ei + er * q;
      const double g0[2] = {(c_ * gr).sum(), (c_ * gi).sum()};
      const double g2[2] = {(c_kx2_ * gr).sum(), (c_kx2_ * gi).sum()};
      for (int k = 0; k < 2; ++k) {
        G0[k] += s * g0[k];
        G2[k] += s * g2[k];
        Gy2[k] += s * ky2_[j] * g0[k];
        Gy4[k] += s * ky4_[j] * g0[k];
        Gxy[k] += s * 2.0 * ky2_[j] * g2[k];  // a_mn = 2 k_m² k_n²
      }
      if (need_g4) {
        G4[0] += s * (c_kx4_ * gr).sum();
        G4[1] += s * (c_kx4_ * gi).sum();
      }
      if (need_w) {
        W[0] += s * (c_ * gr * wn2).sum();
        W[1] += s * (c_ * gi * wn2).sum();
      }
      if (need_h) {
        H[0] += s * (c_ * er * wn).sum();
        H[1] += s * (c_ * ei * wn).sum();
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
  // ω_mn² = K_mn/m'' for the values `v` (the cache's mutex held).
  void update_modes(std::span<const double> v) const {
    PlateCalibration::ModeCache& cache = *cache_;
    if (cache.key.size() == v.size() && std::equal(v.begin(), v.end(), cache.key.begin())) return;
    const int columns = plate_.circumferential_modes + 1;
    cache.omega2.resize(columns, plate_.lateral_modes);
    const KroppPlate geometry(plate_);
    for (int n = 1; n <= plate_.lateral_modes; ++n) {
      const double k = geometry.wavenumber_y(n);
      const double ky2 = k * k;
      const double base = v[bending_y] * ky2 * ky2 + v[tension_y] * ky2 + v[foundation_stiffness];
      const double per_kx2 = v[tension_x] + 2.0 * v[bending_xy] * ky2;
      cache.omega2.col(n - 1) = (base + per_kx2 * kx2_ + v[bending_x] * kx4_) / v[mass_per_area];
    }
    cache.omega_n = cache.omega2.sqrt();
    cache.key.assign(v.begin(), v.end());
  }

  std::shared_ptr<PlateCalibration::ModeCache> cache_;
  PlateParameters plate_;
  double modal_area_ = 0.0;  // L·b/2: the modal mass is m''·L·b/2
  Eigen::ArrayXd kx2_, kx4_, c_, c_kx2_, c_kx4_;
  std::vector<Eigen::Index> lateral_;  // lateral orders (n − 1) with s_n ≠ 0
  std::vector<double> ky2_, ky4_, s_;
};

}  // namespace

PlateCalibration::PlateCalibration(const PlateParameters& plate)
    : plate_(plate), cache_(std::make_shared<ModeCache>()) {
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
  return std::make_unique<PlateReceptance>(plate_, clamped, cache_);
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
