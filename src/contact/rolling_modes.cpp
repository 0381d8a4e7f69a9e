#include "contact/rolling_modes.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rollnoise {

RollingModes::RollingModes(const ModalTyre& tyre, const TyreGrid& grid, double time_step, int substeps)
    : tyre_(tyre),
      grid_(grid),
      time_step_(time_step),
      substeps_(substeps),
      orders_(tyre.orders()),
      lateral_modes_(tyre.lateral_modes()) {
  grid_.validate();
  if (substeps_ < 1) throw std::invalid_argument("rolling tyre: substeps must be >= 1");
  if (std::abs(tyre.circumference() - grid_.circumference()) > 1e-12 * grid_.circumference())
    throw std::invalid_argument("the tyre model and the grid have different radii");
  if (orders_ > grid_.circumferential / 2) {
    throw std::invalid_argument("circumferential_modes = " + std::to_string(orders_) +
                                " exceeds what points_circumferential = " +
                                std::to_string(grid_.circumferential) + " can represent (at most " +
                                std::to_string(grid_.circumferential / 2) + ")");
  }
  lateral_shapes_.resize(grid_.lateral, lateral_modes_);
  for (int j = 0; j < grid_.lateral; ++j)
    for (int l = 0; l < lateral_modes_; ++l) lateral_shapes_(j, l) = tyre.lateral_shape(l, grid_.y(j));
  modes_.reserve(static_cast<std::size_t>((orders_ + 1) * lateral_modes_));
  for (int l = 0; l < lateral_modes_; ++l)
    for (int m = 0; m <= orders_; ++m) modes_.push_back(tyre.mode_response(m, l, grid_.dx(), grid_.dy()));
}

double RollingModes::passing_rate(int m) const {
  // k_m·v with v = dx/(p·Δt): order m turns by 2πm/(p·Nθ) per step.
  return 2.0 * std::numbers::pi * m / (grid_.circumferential * substeps_ * time_step_);
}

void RollingModes::add_modal_sum(const std::vector<std::complex<double>>& coefficients, Eigen::MatrixXd& out) const {
  const int nw = grid_.window;
  const int ny = grid_.lateral;
  const int big_n = grid_.circumferential;
  // a_l(Δ) for Δ = i_p − i_q from −(Nw−1) to Nw−1.
  Eigen::MatrixXd a(2 * nw - 1, lateral_modes_);
  for (int d = -(nw - 1); d <= nw - 1; ++d) {
    for (int l = 0; l < lateral_modes_; ++l) {
      double sum = 0.0;
      for (int m = 0; m <= orders_; ++m) {
        // e^{2πi m Δ/Nθ}, with the angle reduced exactly in integers.
        const long turns = (static_cast<long>(m) * d) % big_n;
        const std::complex<double> e = std::polar(1.0, 2.0 * std::numbers::pi * static_cast<double>(turns) / big_n);
        sum += weight(m) * (e * coefficients[static_cast<std::size_t>(mode_index(m, l))]).real();
      }
      a(d + nw - 1, l) = sum;
    }
  }
  // Block (j_p, j_q) of lateral shapes for each Δ.
  const Eigen::MatrixXd& s = lateral_shapes_;
  for (int d = -(nw - 1); d <= nw - 1; ++d) {
    const Eigen::MatrixXd block = s * a.row(d + nw - 1).asDiagonal() * s.transpose();  // Ny × Ny
    for (int ip = std::max(0, d); ip < nw && ip - d < nw; ++ip) {
      const int iq = ip - d;
      for (int jp = 0; jp < ny; ++jp)
        for (int jq = 0; jq < ny; ++jq) out(ip + nw * jp, iq + nw * jq) += block(jp, jq);
    }
  }
}

DiscreteKernel RollingModes::sheared_kernel(std::size_t lags) const {
  DiscreteKernel kernel;
  kernel.time_step = time_step_;
  kernel.discretisation = Discretisation::step;
  for (std::size_t k = 0; k < lags; ++k) kernel.lags.push_back(sheared_lag(k));
  kernel.total = rolling_compliance();
  return kernel;
}

Eigen::MatrixXd RollingModes::sheared_lag(std::size_t k) const {
  // G̃_ml[k] = ∫_{kΔt}^{(k+1)Δt} e^{iω_m τ} h_ml(τ) dτ in closed form.
  const double dt = time_step_;
  const double t0 = static_cast<double>(k) * dt;
  std::vector<std::complex<double>> coefficients(modes_.size());
  for (int l = 0; l < lateral_modes_; ++l)
    for (int m = 0; m <= orders_; ++m) {
      const auto r = static_cast<std::size_t>(mode_index(m, l));
      coefficients[r] = modes_[r].phase_integral(passing_rate(m), t0, t0 + dt);
    }
  Eigen::MatrixXd lag = Eigen::MatrixXd::Zero(grid_.points(), grid_.points());
  add_modal_sum(coefficients, lag);
  return lag;
}

Eigen::MatrixXd RollingModes::rolling_compliance() const {
  // Σ_k G̃[k] = ∫_0^∞ e^{iωτ} h dτ = α(−ω), the receptance with the e^{−iωt} convention.
  std::vector<std::complex<double>> coefficients(modes_.size());
  for (int l = 0; l < lateral_modes_; ++l)
    for (int m = 0; m <= orders_; ++m) {
      const auto r = static_cast<std::size_t>(mode_index(m, l));
      coefficients[r] = modes_[r].steady_total(passing_rate(m));
    }
  Eigen::MatrixXd total = Eigen::MatrixXd::Zero(grid_.points(), grid_.points());
  add_modal_sum(coefficients, total);
  return total;
}

}  // namespace rollnoise
