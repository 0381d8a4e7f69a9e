#include "greens/two_layer_tyre.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "greens/sinc.hpp"

namespace rollnoise {
namespace {

using cd = std::complex<double>;
using std::numbers::pi;


void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

TwoLayerStack make_two_layer_stack(const TwoLayerParameters& p) {
  if (const std::string problem = orthotropic_problem(p.belt, "belt_"); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  require(positive(p.tread_youngs_modulus), "tread_youngs_modulus must be finite and > 0");
  require(p.tread_poisson_ratio > -1.0 && p.tread_poisson_ratio < 0.5,
          "tread_poisson_ratio must lie strictly between -1 and 0.5 (0.5, incompressible, has no finite stiffness)");
  for (const auto& [value, name] : {std::pair{p.belt_loss_factor, "belt_loss_factor"},
                                    {p.tread_loss_factor, "tread_loss_factor"},
                                    {p.foundation_loss_factor, "foundation_loss_factor"}}) {
    try {
      const CausalModulus check(value);
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument(std::string(name) + ": " + error.what());
    }
  }
  const ElasticLayer belt{orthotropic_stiffness(p.belt), p.belt_density, p.belt_thickness, p.belt_loss_factor};
  const ElasticLayer tread{
      orthotropic_stiffness(OrthotropicConstants::isotropic(p.tread_youngs_modulus, p.tread_poisson_ratio)),
      p.tread_density, p.tread_thickness, p.tread_loss_factor};
  return TwoLayerStack(belt, tread, p.tension_x, p.tension_y, p.foundation_stiffness, p.foundation_loss_factor);
}

TwoLayerTyre::TwoLayerTyre(const TwoLayerParameters& parameters)
    : p_(parameters), stack_(make_two_layer_stack(parameters)) {
  require(positive(p_.radius), "radius must be finite and > 0");
  require(positive(p_.width), "width must be finite and > 0");
  require(p_.circumferential_modes >= 0, "circumferential_modes must be >= 0");
  require(p_.lateral_modes >= 1, "lateral_modes must be >= 1");
  // The sliding edges' n = 0, m = 0 mode is a rigid normal translation of the whole strip: only
  // the foundation holds it.
  require(p_.side_condition == SideCondition::simply_supported || p_.foundation_stiffness > 0.0,
          "foundation_stiffness must be > 0 with side_condition = \"sliding\" (otherwise the tyre has a "
          "free rigid-body mode)");
  length_ = 2.0 * pi * p_.radius;
}

int TwoLayerTyre::first_lateral_order() const noexcept {
  return p_.side_condition == SideCondition::simply_supported ? 1 : 0;
}

int TwoLayerTyre::last_lateral_order() const noexcept { return first_lateral_order() + p_.lateral_modes - 1; }

double TwoLayerTyre::wavenumber_x(int m) const noexcept { return 2.0 * pi * static_cast<double>(m) / length_; }

double TwoLayerTyre::wavenumber_y(int n) const noexcept { return pi * static_cast<double>(n) / p_.width; }

double TwoLayerTyre::lateral_shape(SurfaceDirection d, int n, double y) const noexcept {
  const double arg = wavenumber_y(n) * y;
  const bool sine = (d == SurfaceDirection::y) == (p_.side_condition == SideCondition::sliding);
  return sine ? std::sin(arg) : std::cos(arg);
}

double TwoLayerTyre::modal_norm(int n) const noexcept { return length_ * (n == 0 ? p_.width : 0.5 * p_.width); }

Eigen::Matrix3cd TwoLayerTyre::wavenumber_compliance(double kx, double ky, cd omega) const {
  return stack_.surface_compliance(kx, ky, omega);
}

Eigen::Matrix3cd TwoLayerTyre::modal_compliance(int m, int n, cd omega) const {
  Eigen::Matrix3cd h = stack_.surface_compliance(wavenumber_x(m), wavenumber_y(n), omega);
  // H = D⁻¹ĜD (simply supported) or DĜD⁻¹ (sliding), D = diag(1, i, 1): only the entries that
  // couple y to x or z change, by a factor ±i. (At k = 0, ω = 0 the in-plane entries are
  // infinite and the couplings exactly 0; leave them so.)
  const cd i(0.0, 1.0);
  const cd into_y = p_.side_condition == SideCondition::simply_supported ? -i : i;  // row y
  for (int c : {0, 2}) {
    if (h(1, c) != 0.0) h(1, c) *= into_y;
    if (h(c, 1) != 0.0) h(c, 1) /= into_y;
  }
  return h;
}

std::unique_ptr<SurfaceResponse> TwoLayerTyre::at(cd omega) const {
  return std::unique_ptr<SurfaceResponse>(new TwoLayerResponse(*this, omega));
}

TwoLayerResponse::TwoLayerResponse(const TwoLayerTyre& tyre, cd omega) : tyre_(&tyre), omega_(omega) {
  if (!std::isfinite(omega.real()) || !std::isfinite(omega.imag()) || omega.imag() > 0.0) {
    throw std::invalid_argument("two_layer: omega must be finite with Im omega <= 0");
  }
  const int columns = tyre.parameters().circumferential_modes + 1;
  const int first = tyre.first_lateral_order();
  table_.reserve(static_cast<std::size_t>(columns * tyre.parameters().lateral_modes));
  for (int n = first; n <= tyre.last_lateral_order(); ++n) {
    for (int m = 0; m < columns; ++m) table_.push_back(tyre.modal_compliance(m, n, omega));
  }
}

const Eigen::Matrix3cd& TwoLayerResponse::modal_compliance(int m, int n) const {
  const int columns = tyre_->parameters().circumferential_modes + 1;
  const int row = n - tyre_->first_lateral_order();
  if (m < 0 || m >= columns || row < 0 || row >= tyre_->parameters().lateral_modes) {
    throw std::out_of_range("two_layer: mode (" + std::to_string(m) + ", " + std::to_string(n) + ") is not in the table");
  }
  return table_[static_cast<std::size_t>(row * columns + m)];
}

cd TwoLayerResponse::receptance(const SurfaceLocation& receiver, const SurfaceLocation& source,
                                SurfaceDirection response, SurfaceDirection load) const {
  const TwoLayerTyre& t = *tyre_;
  const double b = t.width();
  for (const SurfaceLocation* s : {&receiver, &source}) {
    // Grid positions computed as (j + ½)·Δy may overshoot by a rounding error: allow that.
    const double slack = 1e-9 * b;
    if (!std::isfinite(s->x) || !(s->length >= 0.0) || !(s->width >= 0.0) || !std::isfinite(s->length) ||
        !(s->y - 0.5 * s->width >= -slack) || !(s->y + 0.5 * s->width <= b + slack)) {
      throw std::invalid_argument("two_layer: a location must be finite with its cell inside the width [0, " +
                                  std::to_string(b) + "] m (got y = " + std::to_string(s->y) +
                                  ", width " + std::to_string(s->width) + ")");
    }
  }
  const int i = static_cast<int>(response), j = static_cast<int>(load);
  // H(−m) = ΠH(m)Π: the ±m pair adds as 2cos (even) or 2i·sin (one index along x).
  const bool odd = (response == SurfaceDirection::x) != (load == SurfaceDirection::x);
  const double length = t.circumference();
  const double xr = std::remainder(receiver.x, length), xs = std::remainder(source.x, length);
  const int columns = t.parameters().circumferential_modes + 1;
  // Circumferential factors per m: phase pair and the cells' means.
  thread_local std::vector<cd> circumferential;
  circumferential.resize(static_cast<std::size_t>(columns));
  for (int m = 0; m < columns; ++m) {
    const double k = t.wavenumber_x(m);
    const cd phase = std::polar(1.0, k * xr) * std::polar(1.0, -k * xs);  // e^{ik(x_r − x_s)}
    const double cells = sinc(0.5 * k * receiver.length) * sinc(0.5 * k * source.length);
    const cd pair = m == 0 ? cd(1.0) : (odd ? phase - std::conj(phase) : phase + std::conj(phase));
    circumferential[static_cast<std::size_t>(m)] = pair * cells;
  }
  cd sum = 0.0;
  for (int n = t.first_lateral_order(); n <= t.last_lateral_order(); ++n) {
    const double ky = t.wavenumber_y(n);
    const double lateral = t.lateral_shape(response, n, receiver.y) * sinc(0.5 * ky * receiver.width) *
                           t.lateral_shape(load, n, source.y) * sinc(0.5 * ky * source.width) / t.modal_norm(n);
    if (lateral == 0.0) continue;
    cd inner = 0.0;
    for (int m = 0; m < columns; ++m) {
      const cd h = modal_compliance(m, n)(i, j);
      if (!std::isfinite(h.real())) {
        throw std::domain_error(
            "two_layer: the static in-plane compliance of the sliding edges' uniform mode (n = 0, m = 0) is "
            "unbounded (a free in-plane translation); ask for the normal response or at omega != 0");
      }
      inner += h * circumferential[static_cast<std::size_t>(m)];
    }
    sum += lateral * inner;
  }
  return sum;
}

}  // namespace rollnoise
