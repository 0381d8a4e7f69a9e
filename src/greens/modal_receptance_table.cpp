#include "greens/modal_receptance_table.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "greens/two_layer_tyre.hpp"

namespace rollnoise {
namespace {

using std::numbers::pi;

std::string indexed(const std::string& dataset, std::size_t i) { return dataset + "[" + std::to_string(i) + "]"; }

}  // namespace

double ModalReceptanceTable::circumference() const noexcept { return 2.0 * pi * radius; }

double ModalReceptanceTable::wavenumber_x(int m) const noexcept {
  return 2.0 * pi * static_cast<double>(m) / circumference();
}

double ModalReceptanceTable::wavenumber_y(int n) const noexcept { return pi * static_cast<double>(n) / width; }

double ModalReceptanceTable::modal_norm(int n) const noexcept {
  const bool uniform = lateral_shape == LateralShape::cosine && n == 0;
  return circumference() * (uniform ? width : 0.5 * width);
}

double ModalReceptanceTable::lateral_shape_value(int n, double y) const noexcept {
  const double arg = wavenumber_y(n) * y;
  return lateral_shape == LateralShape::sine ? std::sin(arg) : std::cos(arg);
}

std::size_t ModalReceptanceTable::mode_index(int m, int n) const {
  const int row = n - first_lateral_order;
  if (m < 0 || m > orders || row < 0 || row >= lateral_orders) {
    throw std::out_of_range("modal receptance table: mode (m = " + std::to_string(m) + ", n = " + std::to_string(n) +
                            ") is not in the table (m = 0 … " + std::to_string(orders) + ", n = " +
                            std::to_string(first_lateral_order) + " … " + std::to_string(last_lateral_order()) + ")");
  }
  return static_cast<std::size_t>(row) * static_cast<std::size_t>(orders + 1) + static_cast<std::size_t>(m);
}

void ModalReceptanceTable::validate() const {
  const auto fail = [&](const std::string& where, const std::string& problem) {
    throw InputError(source, where, problem);
  };
  if (!(std::isfinite(radius) && radius > 0.0)) {
    fail("/ attribute radius_m", "must be a finite number > 0 (got " + format_number(radius) + ")");
  }
  if (!(std::isfinite(width) && width > 0.0)) {
    fail("/ attribute width_m", "must be a finite number > 0 (got " + format_number(width) + ")");
  }
  // sin(0·y) = 0: a sine table has no n = 0 mode.
  const int lowest = lateral_shape == LateralShape::sine ? 1 : 0;
  if (first_lateral_order < lowest) {
    fail("/ attribute first_lateral_order",
         "must be >= " + std::to_string(lowest) + " for lateral_shape \"" +
             (lateral_shape == LateralShape::sine ? "sine" : "cosine") + "\" (got " +
             std::to_string(first_lateral_order) + ")");
  }
  if (lateral_orders < 1) fail("/lateral_order", "must hold at least one lateral order");
  if (orders < 0) fail("/order", "must hold at least the order m = 0");
  if (frequency.size() < 1) fail("/frequency", "must hold at least one frequency");
  for (Eigen::Index k = 0; k < frequency.size(); ++k) {
    const double f = frequency(k);
    const std::string where = indexed("/frequency", static_cast<std::size_t>(k));
    if (!std::isfinite(f)) fail(where, "must be a finite number (Hz)");
    if (f < 0.0) fail(where, "is " + format_number(f) + " Hz; frequencies must be >= 0");
    if (k > 0 && !(f > frequency(k - 1))) {
      fail(where, format_number(f) + " Hz is not greater than the value before (" + format_number(frequency(k - 1)) +
                      " Hz); frequencies must be strictly increasing");
    }
  }
  const std::size_t count = static_cast<std::size_t>(lateral_orders) * static_cast<std::size_t>(orders + 1);
  if (modes.size() != count) {
    fail("/receptance_re", "holds " + std::to_string(modes.size()) + " modes; " + std::to_string(lateral_orders) +
                               " lateral orders × " + std::to_string(orders + 1) + " orders make " +
                               std::to_string(count));
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (modes[i].size() != frequency.size()) {
      fail(indexed("/receptance_re", i), "holds " + std::to_string(modes[i].size()) + " values; one per frequency (" +
                                             std::to_string(frequency.size()) + ") is needed");
    }
    for (Eigen::Index k = 0; k < frequency.size(); ++k) {
      const std::complex<double> h = modes[i](k);
      const std::string at = "[" + std::to_string(i) + "][" + std::to_string(k) + "]";
      if (!std::isfinite(h.real())) fail("/receptance_re" + at, "must be a finite number (m/Pa)");
      if (!std::isfinite(h.imag())) fail("/receptance_im" + at, "must be a finite number (m/Pa)");
    }
  }
}

std::complex<double> two_layer_entry(const TwoLayerTyre& tyre, int m, int n, double frequency_hz) {
  return tyre.modal_compliance(m, n, std::complex<double>(2.0 * pi * frequency_hz, 0.0))(2, 2);
}

ModalReceptanceTable tabulate_two_layer(const TwoLayerTyre& tyre, const Eigen::VectorXd& frequency_hz, int orders,
                                        unsigned threads) {
  if (orders < 0) throw std::invalid_argument("tabulate_two_layer: orders must be >= 0");
  ModalReceptanceTable table;
  table.radius = tyre.parameters().radius;
  table.width = tyre.parameters().width;
  table.lateral_shape =
      tyre.parameters().side_condition == SideCondition::simply_supported ? LateralShape::sine : LateralShape::cosine;
  table.first_lateral_order = tyre.first_lateral_order();
  table.lateral_orders = tyre.parameters().lateral_modes;
  table.orders = orders;
  table.frequency = frequency_hz;
  table.source = "two_layer";
  // The frequencies first, so that a bad one is reported before the long computation.
  for (Eigen::Index k = 0; k < frequency_hz.size(); ++k) {
    const double f = frequency_hz(k);
    if (!std::isfinite(f) || f < 0.0 || (k > 0 && !(f > frequency_hz(k - 1)))) {
      throw std::invalid_argument("tabulate_two_layer: frequencies must be finite, >= 0 and strictly increasing (" +
                                  indexed("frequency", static_cast<std::size_t>(k)) + " = " + format_number(f) + ")");
    }
  }
  if (frequency_hz.size() == 0) throw std::invalid_argument("tabulate_two_layer: no frequencies");
  const std::size_t count = static_cast<std::size_t>(table.lateral_orders) * static_cast<std::size_t>(orders + 1);
  table.modes.assign(count, Eigen::VectorXcd(frequency_hz.size()));

  // Each thread takes the next frequency not yet taken (costs differ between frequencies) and
  // writes only that frequency's column: the values do not depend on who computed them.
  const std::size_t frequencies = static_cast<std::size_t>(frequency_hz.size());
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t workers = std::min<std::size_t>(threads == 0 ? hardware : threads, frequencies);
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> failures(workers);
  const auto work = [&](std::size_t worker) {
    try {
      for (std::size_t k = next++; k < frequencies; k = next++) {
        const Eigen::Index column = static_cast<Eigen::Index>(k);
        for (int n = table.first_lateral_order; n <= table.last_lateral_order(); ++n) {
          for (int m = 0; m <= orders; ++m) {
            table.modes[table.mode_index(m, n)](column) = two_layer_entry(tyre, m, n, frequency_hz(column));
          }
        }
      }
    } catch (...) {
      failures[worker] = std::current_exception();
      next = frequencies;  // the others stop too
    }
  };
  {
    std::vector<std::jthread> pool;
    for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work, t);
    work(0);
  }  // joined here
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
  table.validate();
  return table;
}

Eigen::VectorXd default_fit_frequencies(int count, double lowest, double highest) {
  if (count < 2 || !(lowest > 0.0) || !(highest > lowest) || !std::isfinite(highest)) {
    throw std::invalid_argument("default_fit_frequencies: need count >= 2 and 0 < lowest < highest");
  }
  Eigen::VectorXd f(count + 1);
  f(0) = 0.0;
  const double ratio = std::log(highest / lowest);
  for (int k = 0; k < count; ++k) {
    f(k + 1) = lowest * std::exp(ratio * static_cast<double>(k) / static_cast<double>(count - 1));
  }
  // The ends exactly as asked, not as exp(log(·)) rounds them.
  f(1) = lowest;
  f(count) = highest;
  return f;
}

}  // namespace rollnoise
