#include "radiation/tyre_radiation.hpp"

#include "radiation/least_squares.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <thread>

#include "core/fftw_plan.hpp"
#include "core/progress.hpp"
#include "core/real_fft_batch.hpp"
#include "radiation/belt_sampling.hpp"
#include "radiation/transfer_table.hpp"

namespace rollnoise {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// The lowest anchor: the 20 Hz band is the lowest that rolling-noise spectra show.
constexpr double kLowestAnchorHz = 20.0;
// Zero padding after the record, s: longer than what is left of the receivers' responses once
// the propagation delay is taken out (the horn's ringing dies within a few milliseconds).
constexpr double kPaddingSeconds = 0.03;
// The highest anchor is at most this fraction of the Nyquist frequency.
constexpr double kNyquistFraction = 0.99;
// η₀ of the combined sources (equivalent_sources.hpp), 1/m: the monopole's weight is
// i(k + η₀). η = k alone (the usual choice at high frequency) leaves the sources nearly pure
// dipoles at low frequency, which rebuild a monopole's field poorly (6.6 % at 500 Hz, 40 % at
// 100 Hz on the runs' mesh); η₀ about the inverse of the sources' depth (2–3 cm) balances the
// two there. With η₀ = 50 the interior-monopole checks (test_deformed_mesh.cpp, on the stage's
// meshes) stayed within 1.4 % of the incoherent direct + image amplitude below 1.5 kHz and within
// 4.2 % at every anchor to 5623 Hz (a one-off scan); η₀ = 200 did worse above 4 kHz (on a first
// version of the split mesh, 7.3 % against 3.5 % at 5.3 kHz relative to the exact pressure).
constexpr double kCouplingFloor = 50.0;

// Raise when a change of the stage's solve changes the operators it stores: old cache entries
// then miss (radiation_cache.hpp). The key digests the inputs; this marks the code.
constexpr int kAnchorSolveRevision = 1;

// What one anchor gives: the transfer to the receivers, and its hat-weighted share of the power
// of the bins around it.
struct AnchorResult {
  Eigen::MatrixXcd transfer;         // R × A
  std::vector<Eigen::Index> bins;    // indices into the band's bins
  std::vector<double> power;         // W, weighted
  bool from_cache = false;
  Eigen::Index power_rank = 0;
};

void digest_points(FnvDigest& d, const Eigen::Matrix3Xd& m) {
  d.integer(m.cols());
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < 3; ++i) d.real(m(i, j));
}

}  // namespace

EquivalentSources make_tyre_model(const TyreSurfaceMesh& mesh, const Medium& medium, bool combined) {
  std::optional<CombinedSources> layer;
  if (combined) layer = CombinedSources{mesh.source_normals, 1.0, kCouplingFloor};
  return EquivalentSources(mesh.sources, mesh.points, mesh.normals, true, medium, EquivalentSources::Symmetry::automatic,
                           std::move(layer));
}

std::vector<RadiationMeshLevel> radiation_mesh_levels(const TyreRadiationSettings& settings) {
  const TyreSurfaceMeshSpec& base = settings.mesh;
  if (!(settings.sample_rate_hz >= 0.0) || !std::isfinite(settings.sample_rate_hz))
    throw std::invalid_argument("tyre radiation: the sample rate must be >= 0 (0: not known)");
  const double top = settings.sample_rate_hz > 0.0 ? std::min(settings.max_frequency_hz, kNyquistFraction * 0.5 * settings.sample_rate_hz)
                                                   : settings.max_frequency_hz;
  std::vector<RadiationMeshLevel> out{{base, top}};
  const double n = settings.points_per_wavelength;
  if (!(n >= 0.0) || !std::isfinite(n)) throw std::invalid_argument("tyre radiation: points per wavelength must be >= 0");
  if (n == 0.0) return out;
  const double c = settings.medium.sound_speed;
  const double spacing = kTwoPi * base.radius / (base.around * base.tread_split);
  out.front().top_hz = c / (n * spacing);
  for (int split = 2; out.back().top_hz < top; split *= 2) {
    if (split > 8)
      throw std::invalid_argument("tyre radiation: the mesh is too coarse for the maximum frequency (more than an 8-fold split "
                                  "of the tread; raise mesh_around)");
    RadiationMeshLevel level{base, split * out.front().top_hz};
    level.spec.tread_split = base.tread_split * split;
    const double wavelength = c / std::min(level.top_hz, top);
    level.spec.sidewall_rings = std::max(base.sidewall_rings, static_cast<int>(std::ceil(n * base.radius / wavelength)));
    out.push_back(level);
  }
  return out;
}

TyreRadiation::TyreRadiation(const TyreRadiationSettings& settings, Eigen::Matrix3Xd receivers)
    : settings_(settings), receivers_(std::move(receivers)) {
  if (!(settings_.max_frequency_hz > kLowestAnchorHz) || !std::isfinite(settings_.max_frequency_hz))
    throw std::invalid_argument("tyre radiation: the maximum frequency must be above 20 Hz");
  if (!(settings_.anchor_spacing_hz >= 5.0 && settings_.anchor_spacing_hz <= 1000.0))
    throw std::invalid_argument("tyre radiation: the anchor spacing must be within 5 ... 1000 Hz");
  if (!(settings_.combined_sources_above_hz >= 0.0)) throw std::invalid_argument("tyre radiation: combined_sources_above_hz must be >= 0");
  if (settings_.threads < 0) throw std::invalid_argument("tyre radiation: threads must be >= 0");
  if (receivers_.cols() == 0) throw std::invalid_argument("tyre radiation: no receivers");
  for (const RadiationMeshLevel& level : radiation_mesh_levels(settings_)) {
    TyreSurfaceMesh mesh = make_tyre_surface_mesh(level.spec);
    EquivalentSources monopoles = make_tyre_model(mesh, settings_.medium, false);
    EquivalentSources combined = make_tyre_model(mesh, settings_.medium, true);
    // The geometry the solve sees, to the bit: whatever in the spec, the deformation or the
    // band's rule shaped the mesh acts through these (and the areas, which the solve does not use,
    // are left out).
    FnvDigest geometry;
    for (const Eigen::Matrix3Xd* m : {&mesh.points, &mesh.normals, &mesh.sources, &mesh.source_normals}) digest_points(geometry, *m);
    geometry.integer(mesh.tread_points);
    levels_.push_back({level.top_hz, level.spec, std::move(mesh), std::move(monopoles), std::move(combined), {}, geometry});
  }
  for (std::size_t l = 0; l + 1 < levels_.size(); ++l) levels_[l].from_input = tread_to_tread_matrix(input_mesh(), levels_[l].mesh);
  centre_ = Eigen::Vector3d(0.0, 0.0, input_mesh().axle_height);
}

std::size_t TyreRadiation::level_of(double anchor_hz) const {
  for (std::size_t l = 0; l < levels_.size(); ++l)
    if (anchor_hz <= levels_[l].top_hz) return l;
  return levels_.size() - 1;
}

std::vector<double> TyreRadiation::anchors(double sample_rate) const {
  if (settings_.sample_rate_hz > 0.0 && sample_rate != settings_.sample_rate_hz)
    throw std::invalid_argument("tyre radiation: the velocities' sample rate differs from the settings'");
  const double top = std::min(settings_.max_frequency_hz, kNyquistFraction * 0.5 * sample_rate);
  if (!(top > kLowestAnchorHz)) throw std::invalid_argument("tyre radiation: the sample rate is too low (below 40 Hz)");
  const double spacing = settings_.anchor_spacing_hz;
  std::vector<double> out{kLowestAnchorHz};
  if (spacing > 2.5 * kLowestAnchorHz && 0.5 * spacing < top) out.push_back(0.5 * spacing);
  for (double f = spacing; f < top; f += spacing)
    if (f > out.back()) out.push_back(f);
  if (top - out.back() > 1e-9 * top) out.push_back(top);
  return out;
}

std::string TyreRadiation::anchor_key(std::size_t level, double anchor_hz, Eigen::Index columns) const {
  FnvDigest d = levels_.at(level).geometry;
  d.text(kRadiationCacheLayout);
  d.integer(kAnchorSolveRevision);
  d.integer(columns);
  digest_points(d, receivers_);
  d.real(settings_.medium.density);
  d.real(settings_.medium.sound_speed);
  d.real(anchor_hz);
  d.real(settings_.regularisation);
  const bool combined = anchor_hz > settings_.combined_sources_above_hz;
  d.integer(combined ? 1 : 0);
  if (combined) {
    d.real(1.0);  // η of make_tyre_model
    d.real(kCouplingFloor);
  }
  d.real(kPowerFactorTolerance);
  // make_tyre_model's choices: the rigid road, the automatic symmetry split, the automatic
  // least-squares method and unweighted collocation.
  d.text("rigid plane; symmetry automatic; least squares automatic; unweighted");
  return kRadiationCachePrefix + d.hex();
}

AnchorOperators TyreRadiation::solve_anchor(std::size_t level_index, double anchor_hz, Eigen::Index columns) const {
  const Level& level = levels_.at(level_index);
  const double omega = kTwoPi * anchor_hz;
  const EquivalentSources& model = anchor_hz > settings_.combined_sources_above_hz ? level.combined : level.monopoles;
  const EquivalentSourceSolve solve = model.solve(omega, settings_.regularisation);
  AnchorOperators out;
  out.transfer = solve.transfer(model.pressure_matrix(omega, receivers_)).leftCols(columns);
  out.power = model.power_operator(solve, omega, columns);
  return out;
}

RadiatedSound TyreRadiation::radiate(const Eigen::MatrixXd& surface_velocity, double sample_rate,
                                     ProgressReporter* progress, const RadiationCache* cache) const {
  const Eigen::Index active = surface_velocity.cols();
  const TyreSurfaceMesh& input = input_mesh();
  if (active != input.tread_points && !(active == input.points.cols() && levels_.size() == 1))
    throw std::invalid_argument(
        "tyre radiation: velocities for the tread's collocation points (or for all of them when one mesh serves every anchor)");
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
  std::vector<double> seconds(anchor.size(), 0.0);
  // The operators' columns on each level: the tread (the velocities' own columns on the input
  // mesh, which may be every point when one mesh serves every anchor).
  const auto columns_of = [&](std::size_t level) {
    return level + 1 == levels_.size() ? active : static_cast<Eigen::Index>(levels_[level].mesh.tread_points);
  };
  const auto solve_anchor = [&](std::size_t a) {
    const auto started = std::chrono::steady_clock::now();
    struct Clock {
      std::chrono::steady_clock::time_point started;
      double& seconds;
      ~Clock() { seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); }
    } clock{started, seconds[a]};
    const std::size_t level_index = level_of(anchor[a]);
    const Level& level = levels_[level_index];
    const bool own = &level == &levels_.back();  // the input mesh itself
    AnchorResult& out = results[a];
    // From the cache when it has the anchor (loaded here, in the worker, so that only the
    // anchors in hand are in memory), else solved and stored.
    const std::string key = cache ? anchor_key(level_index, anchor[a], columns_of(level_index)) : std::string();
    std::optional<AnchorOperators> cached;
    const EquivalentSources& model = anchor[a] > settings_.combined_sources_above_hz ? level.combined : level.monopoles;
    if (cache) cached = cache->load(key, receivers_.cols(), columns_of(level_index), model.point_coordinate_counts(columns_of(level_index)));
    AnchorOperators operators;
    if (cached) {
      operators = std::move(*cached);
      out.from_cache = true;
    } else {
      operators = this->solve_anchor(level_index, anchor[a], columns_of(level_index));
      if (cache) {
        const AnchorDescription description{anchor[a], level.mesh.points.cols(), level.mesh.sources.cols(), level.spec.tread_split,
                                            level.spec.sidewall_rings,
                                            anchor[a] > settings_.combined_sources_above_hz ? "combined" : "monopoles"};
        cache->store(key, operators, description);
      }
    }
    out.power_rank = operators.power_rank();
    if (own)
      out.transfer = std::move(operators.transfer);
    else
      out.transfer = operators.transfer * level.from_input;
    const double below = a > 0 ? anchor[a - 1] : anchor[a];
    const double above = a + 1 < anchor.size() ? anchor[a + 1] : anchor[a];
    for (Eigen::Index b = 0; b < band; ++b)
      if (frequency(b) >= below && frequency(b) <= above && (frequency(b) > below || a == 0)) out.bins.push_back(b);
    if (out.bins.empty()) return;
    Eigen::MatrixXcd velocities(columns_of(level_index), static_cast<Eigen::Index>(out.bins.size()));
    for (std::size_t i = 0; i < out.bins.size(); ++i) {
      const auto c = static_cast<Eigen::Index>(i);
      if (own)
        velocities.col(c) = spectra.col(out.bins[i]);
      else
        velocities.col(c) = level.from_input * spectra.col(out.bins[i]);
    }
    // W = ½ Σ_c ‖Q_c x_c‖² (EquivalentSources::power_operator).
    const std::vector<Eigen::MatrixXcd> coordinates = model.point_coordinates(velocities);
    Eigen::VectorXd squares = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(out.bins.size()));
    for (std::size_t c = 0; c < coordinates.size(); ++c) {
      if (operators.power[c].rows() == 0) continue;
      const Eigen::MatrixXcd amplitudes = blas_product(operators.power[c], coordinates[c]);
      for (Eigen::Index i = 0; i < amplitudes.cols(); ++i) squares(i) += amplitudes.col(i).squaredNorm();
    }
    for (std::size_t i = 0; i < out.bins.size(); ++i) {
      const double f = frequency(out.bins[i]);
      const double hat = f < anchor[a] ? (f - below) / (anchor[a] - below)
                         : f > anchor[a] ? (above - f) / (above - anchor[a])
                                         : 1.0;
      out.power.push_back(hat * power_scale * 0.5 * squares(static_cast<Eigen::Index>(i)));
    }
  };

  // Anchors in parallel: each worker takes the next unsolved one.
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const auto workers = std::min<std::size_t>(anchor.size(), settings_.threads > 0 ? static_cast<std::size_t>(settings_.threads) : cores);
  // The costliest (finest) first, so that the threads finish together; the results go to
  // their anchors' places whatever the order.
  std::vector<std::size_t> order(anchor.size());
  for (std::size_t a = 0; a < anchor.size(); ++a) order[a] = a;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return level_of(anchor[x]) > level_of(anchor[y]); });
  std::atomic<std::size_t> next{0};
  std::size_t finished = 0;
  std::mutex mutex;
  std::exception_ptr failure;
  const auto work = [&] {
    for (std::size_t i = next++; i < anchor.size(); i = next++) {
      const std::size_t a = order[i];
      try {
        solve_anchor(a);
        const std::lock_guard lock(mutex);
        ++finished;
        // May throw Interrupted (Ctrl-C): stops every worker like a failure.
        if (progress) progress->update(finished);
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!failure) failure = std::current_exception();
        next = anchor.size();
      }
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
  out.anchors_hz = anchor;
  for (double f : anchor) out.anchor_mesh.push_back(level_of(f));
  out.anchor_seconds = seconds;
  for (const AnchorResult& r : results) {
    out.anchor_from_cache.push_back(r.from_cache);
    out.anchor_power_rank.push_back(r.power_rank);
  }
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
