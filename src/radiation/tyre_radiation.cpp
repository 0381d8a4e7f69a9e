#include "radiation/tyre_radiation.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <thread>

#include "core/fftw_plan.hpp"
#include "core/progress.hpp"
#include "core/real_fft_batch.hpp"
#include "radiation/transfer_table.hpp"

namespace rollnoise {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// The lowest anchor: the 20 Hz band is the lowest that rolling-noise spectra show.
constexpr double kLowestAnchorHz = 20.0;
// Zero padding after the record, s: longer than what is left of the receivers' responses once
// the propagation delay is taken out (the horn's ringing dies within a few milliseconds).
constexpr double kPaddingSeconds = 0.03;

// What one anchor's solve gives: the transfer to the receivers, and its hat-weighted share of
// the power of the bins around it.
struct AnchorResult {
  Eigen::MatrixXcd transfer;         // R × A
  std::vector<Eigen::Index> bins;    // indices into the band's bins
  std::vector<double> power;         // W, weighted
};

}  // namespace

TyreRadiation::TyreRadiation(const TyreRadiationSettings& settings, Eigen::Matrix3Xd receivers)
    : settings_(settings),
      mesh_(make_tyre_surface_mesh(settings.mesh)),
      model_(mesh_.sources, mesh_.points, mesh_.normals, true, settings.medium),
      receivers_(std::move(receivers)),
      centre_(0.0, 0.0, mesh_.axle_height) {
  if (!(settings_.max_frequency_hz > kLowestAnchorHz) || !std::isfinite(settings_.max_frequency_hz))
    throw std::invalid_argument("tyre radiation: the maximum frequency must be above 20 Hz");
  if (!(settings_.anchor_spacing_hz >= 5.0 && settings_.anchor_spacing_hz <= 1000.0))
    throw std::invalid_argument("tyre radiation: the anchor spacing must be within 5 ... 1000 Hz");
  if (settings_.threads < 0) throw std::invalid_argument("tyre radiation: threads must be >= 0");
  if (receivers_.cols() == 0) throw std::invalid_argument("tyre radiation: no receivers");
}

std::vector<double> TyreRadiation::anchors(double sample_rate) const {
  const double top = std::min(settings_.max_frequency_hz, 0.99 * 0.5 * sample_rate);
  if (!(top > kLowestAnchorHz)) throw std::invalid_argument("tyre radiation: the sample rate is too low (below 40 Hz)");
  const double spacing = settings_.anchor_spacing_hz;
  std::vector<double> out{kLowestAnchorHz};
  if (spacing > 2.5 * kLowestAnchorHz && 0.5 * spacing < top) out.push_back(0.5 * spacing);
  for (double f = spacing; f < top; f += spacing)
    if (f > out.back()) out.push_back(f);
  if (top - out.back() > 1e-9 * top) out.push_back(top);
  return out;
}

RadiatedSound TyreRadiation::radiate(const Eigen::MatrixXd& surface_velocity, double sample_rate,
                                     ProgressReporter* progress) const {
  const Eigen::Index active = surface_velocity.cols();
  if (active != mesh_.points.cols() && active != mesh_.tread_points)
    throw std::invalid_argument("tyre radiation: velocities for all collocation points or for the tread's");
  if (surface_velocity.rows() < 2) throw std::invalid_argument("tyre radiation: need at least 2 samples");
  if (!(sample_rate > 0.0) || !std::isfinite(sample_rate))
    throw std::invalid_argument("tyre radiation: the sample rate must be positive");
  if (!surface_velocity.allFinite()) throw std::invalid_argument("tyre radiation: velocities must be finite");

  const std::vector<double> anchor = anchors(sample_rate);
  const Eigen::Index samples = surface_velocity.rows();
  const auto length = static_cast<int>(
      fft_friendly_size(static_cast<std::size_t>(samples) + static_cast<std::size_t>(std::ceil(kPaddingSeconds * sample_rate))));
  const double bin_hz = sample_rate / length;

  // Spectra of the velocities, steady part removed.
  RealFftBatch velocity_fft(length, static_cast<int>(active));
  for (Eigen::Index m = 0; m < active; ++m) {
    const double mean = surface_velocity.col(m).mean();
    for (int n = 0; n < length; ++n)
      velocity_fft.at(static_cast<int>(m), n) = n < samples ? surface_velocity(n, m) - mean : 0.0;
  }
  velocity_fft.forward();
  const auto first_bin = static_cast<int>(std::ceil(anchor.front() / bin_hz));
  const auto last_bin = std::min(length / 2, static_cast<int>(std::floor(anchor.back() / bin_hz)));
  const Eigen::Index band = std::max(0, last_bin - first_bin + 1);
  Eigen::MatrixXcd spectra(active, band);
  for (Eigen::Index b = 0; b < band; ++b)
    for (Eigen::Index m = 0; m < active; ++m)
      spectra(m, b) = velocity_fft.bin(static_cast<int>(m), first_bin + static_cast<int>(b));
  const auto frequency = [&](Eigen::Index b) { return (first_bin + static_cast<double>(b)) * bin_hz; };

  // Parseval for the zero-padded transform: the mean over the record of a bin's harmonic power
  // is ½qᴴSq·4/(N·L) with q the sources for the raw bin X_k (N samples, L the transform length).
  const double power_scale = 4.0 / (static_cast<double>(samples) * length);
  std::vector<AnchorResult> results(anchor.size());
  const auto solve_anchor = [&](std::size_t a) {
    const double omega = kTwoPi * anchor[a];
    const EquivalentSourceSolve solve = model_.solve(omega, settings_.regularisation);
    AnchorResult& out = results[a];
    out.transfer = solve.transfer(model_.pressure_matrix(omega, receivers_)).leftCols(active);
    const double below = a > 0 ? anchor[a - 1] : anchor[a];
    const double above = a + 1 < anchor.size() ? anchor[a + 1] : anchor[a];
    for (Eigen::Index b = 0; b < band; ++b)
      if (frequency(b) >= below && frequency(b) <= above && (frequency(b) > below || a == 0)) out.bins.push_back(b);
    if (out.bins.empty()) return;
    Eigen::MatrixXcd velocities = Eigen::MatrixXcd::Zero(mesh_.points.cols(), static_cast<Eigen::Index>(out.bins.size()));
    for (std::size_t i = 0; i < out.bins.size(); ++i)
      velocities.col(static_cast<Eigen::Index>(i)).head(active) = spectra.col(out.bins[i]);
    const Eigen::MatrixXcd q = solve.strengths(velocities);
    const Eigen::MatrixXcd sq = model_.power_matrix(omega).cast<std::complex<double>>() * q;
    for (std::size_t i = 0; i < out.bins.size(); ++i) {
      const double f = frequency(out.bins[i]);
      const double hat = f < anchor[a] ? (f - below) / (anchor[a] - below)
                         : f > anchor[a] ? (above - f) / (above - anchor[a])
                                         : 1.0;
      const auto c = static_cast<Eigen::Index>(i);
      out.power.push_back(hat * power_scale * 0.5 * q.col(c).dot(sq.col(c)).real());
    }
  };

  // Anchors in parallel: each worker takes the next unsolved one.
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const auto workers = std::min<std::size_t>(anchor.size(), settings_.threads > 0 ? static_cast<std::size_t>(settings_.threads) : cores);
  std::atomic<std::size_t> next{0};
  std::size_t finished = 0;
  std::mutex mutex;
  std::exception_ptr failure;
  const auto work = [&] {
    for (std::size_t a = next++; a < anchor.size(); a = next++) {
      try {
        solve_anchor(a);
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!failure) failure = std::current_exception();
        next = anchor.size();
      }
      const std::lock_guard lock(mutex);
      ++finished;
      if (progress) progress->update(finished);
    }
  };
  {
    std::vector<std::jthread> pool;
    for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
    work();
  }
  if (failure) std::rethrow_exception(failure);

  RadiatedSound out;
  out.sample_rate = sample_rate;
  out.lowest_hz = anchor.front();
  out.highest_hz = anchor.back();
  out.delays_s = propagation_delays(receivers_, centre_, settings_.medium.sound_speed);
  out.frequency_hz.resize(band);
  for (Eigen::Index b = 0; b < band; ++b) out.frequency_hz(b) = frequency(b);
  out.sound_power_w = Eigen::VectorXd::Zero(band);
  std::vector<Eigen::MatrixXcd> transfers;
  for (AnchorResult& r : results) {
    for (std::size_t i = 0; i < r.bins.size(); ++i) out.sound_power_w(r.bins[i]) += r.power[i];
    transfers.push_back(std::move(r.transfer));
  }
  const TransferTable table(anchor, std::move(transfers), out.delays_s);

  const auto receivers = static_cast<int>(receivers_.cols());
  RealFftBatch pressure_fft(length, receivers);
  for (int r = 0; r < receivers; ++r)
    for (int k = 0; k < pressure_fft.bins(); ++k) pressure_fft.bin(r, k) = 0.0;
  for (Eigen::Index b = 0; b < band; ++b) {
    const Eigen::VectorXcd p = table.reduced_at(frequency(b)) * spectra.col(b);
    for (int r = 0; r < receivers; ++r) pressure_fft.bin(r, first_bin + static_cast<int>(b)) = p(r);
  }
  pressure_fft.backward();
  out.pressure.resize(samples, receivers);
  for (int r = 0; r < receivers; ++r)
    for (Eigen::Index n = 0; n < samples; ++n) out.pressure(n, r) = pressure_fft.at(r, static_cast<int>(n)) / length;
  return out;
}

}  // namespace rollnoise
