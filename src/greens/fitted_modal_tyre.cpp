#include "greens/fitted_modal_tyre.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <thread>

#include "greens/sinc.hpp"

namespace rollnoise {

VectorFittingOptions tyre_mode_fit_options() {
  VectorFittingOptions options;
  options.starting_pole_pairs = 2;
  options.real_poles = 2;  // a start for the rubber's relaxation, a branch cut rather than poles
  options.maximum_pole_pairs = 40;
  options.iterations = 4;
  options.fit_direct = false;  // the response falls like 1/(iωZ): to zero, as Σρ/(iω) does
  options.target_rms_error = 3e-3;
  options.target_max_error = 3e-2;
  options.weighting = FitWeighting::relative;
  return options;
}

Eigen::VectorXd tyre_mode_fit_frequencies() { return default_fit_frequencies(160, 1.0, 2.0e4); }

FittedModalTyre::FittedModalTyre(ModalReceptanceTable table, std::string name, bool includes_tread,
                                 const VectorFittingOptions& options, unsigned threads)
    : table_(std::move(table)), name_(std::move(name)), includes_tread_(includes_tread) {
  table_.validate();
  const auto started = std::chrono::steady_clock::now();
  const int orders = table_.orders;
  const auto count = static_cast<std::size_t>((orders + 1) * table_.lateral_orders);
  std::vector<double> omega(static_cast<std::size_t>(table_.frequency.size()));
  for (std::size_t k = 0; k < omega.size(); ++k)
    omega[k] = 2.0 * std::numbers::pi * table_.frequency(static_cast<Eigen::Index>(k));
  fits_.resize(count);
  std::vector<VectorFittingResult> results(count);
  const auto fit_one = [&](std::size_t index) {
    const int l = static_cast<int>(index / static_cast<std::size_t>(orders + 1));
    const int m = static_cast<int>(index % static_cast<std::size_t>(orders + 1));
    const Eigen::VectorXcd& h = table_.mode(m, table_.first_lateral_order + l);
    results[index] = fit_pole_residue(omega, std::span<const std::complex<double>>(h.data(), static_cast<std::size_t>(h.size())), options);
  };
  unsigned workers = threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : threads;
  workers = static_cast<unsigned>(std::min<std::size_t>(workers, count));
  // Modes dealt round-robin: each is fitted alone, so the result does not depend on `workers`.
  std::vector<std::exception_ptr> failures(workers);
  std::vector<std::jthread> pool;
  for (unsigned w = 0; w < workers; ++w) {
    pool.emplace_back([&, w] {
      try {
        for (std::size_t index = w; index < count; index += workers) fit_one(index);
      } catch (...) {
        failures[w] = std::current_exception();
      }
    });
  }
  pool.clear();  // joins
  for (const auto& failure : failures)
    if (failure) std::rethrow_exception(failure);
  std::vector<double> rms(count), max(count);
  std::vector<char> converged(count);
  for (std::size_t index = 0; index < count; ++index) {
    fits_[index] = results[index].response;
    rms[index] = results[index].rms_error;
    max[index] = results[index].max_error;
    converged[index] = results[index].converged ? 1 : 0;
  }
  summarise(rms, max, converged);
  report_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

FittedModalTyre::FittedModalTyre(ModalReceptanceTable table, std::string name, bool includes_tread,
                                 std::vector<PoleResidueResponse> fits, const VectorFittingOptions& options)
    : table_(std::move(table)), name_(std::move(name)), includes_tread_(includes_tread), fits_(std::move(fits)) {
  table_.validate();
  const auto started = std::chrono::steady_clock::now();
  const int orders = table_.orders;
  const auto count = static_cast<std::size_t>((orders + 1) * table_.lateral_orders);
  if (fits_.size() != count) throw std::invalid_argument("fitted modal tyre: the fits do not match the table's modes");
  std::vector<double> rms(count), max(count);
  std::vector<char> converged(count);
  for (std::size_t index = 0; index < count; ++index) {
    fits_[index].validate();
    const int l = static_cast<int>(index / static_cast<std::size_t>(orders + 1));
    const int m = static_cast<int>(index % static_cast<std::size_t>(orders + 1));
    const Eigen::VectorXcd& h = table_.mode(m, table_.first_lateral_order + l);
    // As vector_fitting.hpp measures them: relative to each sample (the static one by its real
    // part, which is all a real response carries at ω = 0).
    double sum = 0.0, worst = 0.0;
    for (Eigen::Index k = 0; k < h.size(); ++k) {
      const double omega = 2.0 * std::numbers::pi * table_.frequency(k);
      std::complex<double> fit = fits_[index].receptance(omega), data = h(k);
      if (omega == 0.0) {
        fit = fit.real();
        data = data.real();
      }
      const double e = std::abs(fit - data) / std::abs(data);
      sum += e * e;
      worst = std::max(worst, e);
    }
    rms[index] = std::sqrt(sum / static_cast<double>(h.size()));
    max[index] = worst;
    converged[index] = rms[index] <= options.target_rms_error && worst <= options.target_max_error ? 1 : 0;
  }
  summarise(rms, max, converged);
  report_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

void FittedModalTyre::summarise(const std::vector<double>& rms, const std::vector<double>& max,
                                const std::vector<char>& converged) {
  const int orders = table_.orders;
  report_ = ModalFitReport{};
  report_.modes = fits_.size();
  double sum = 0.0;
  for (std::size_t index = 0; index < fits_.size(); ++index) {
    report_.poles += fits_[index].size();
    report_.unconverged += converged[index] ? 0 : 1;
    sum += rms[index];
    report_.worst_max_error = std::max(report_.worst_max_error, max[index]);
    if (rms[index] >= report_.worst_rms_error) {
      report_.worst_rms_error = rms[index];
      report_.worst_order = static_cast<int>(index % static_cast<std::size_t>(orders + 1));
      report_.worst_lateral_order =
          table_.first_lateral_order + static_cast<int>(index / static_cast<std::size_t>(orders + 1));
    }
  }
  report_.mean_rms_error = fits_.empty() ? 0.0 : sum / static_cast<double>(fits_.size());
}

const PoleResidueResponse& FittedModalTyre::fitted(int m, int l) const {
  if (m < 0 || m > table_.orders || l < 0 || l >= table_.lateral_orders)
    throw std::out_of_range("fitted modal tyre: mode outside the table");
  return fits_[static_cast<std::size_t>(l) * static_cast<std::size_t>(table_.orders + 1) + static_cast<std::size_t>(m)];
}

PoleResidueResponse FittedModalTyre::mode_response(int m, int l, double cell_length, double cell_width) const {
  const int n = table_.first_lateral_order + l;
  const double cx = sinc(0.5 * table_.wavenumber_x(m) * cell_length);
  const double cy = sinc(0.5 * table_.wavenumber_y(n) * cell_width);
  const double scale = cx * cx * cy * cy / table_.modal_norm(n);
  PoleResidueResponse out = fitted(m, l);
  for (auto& residue : out.residues) residue *= scale;
  out.direct *= scale;
  return out;
}

}  // namespace rollnoise
