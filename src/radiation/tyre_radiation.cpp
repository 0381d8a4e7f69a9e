#include "radiation/tyre_radiation.hpp"

#include "radiation/least_squares.hpp"
#include "radiation/quantised_power_operator.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <mutex>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <thread>

#include "core/fftw_plan.hpp"
#include "core/progress.hpp"
#include "core/real_fft_batch.hpp"
#include "radiation/belt_sampling.hpp"
#include "radiation/power_taper.hpp"
#include "radiation/transfer_table.hpp"

namespace rollnoise {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// The lowest anchor: the 20 Hz band is the lowest that rolling-noise spectra show.
constexpr double kLowestAnchorHz = 20.0;
// Zero padding after the record, s: longer than what is left of the receivers' responses once
// the propagation delay is taken out (the horn's ringing dies within a few milliseconds).
constexpr double kPaddingSeconds = 0.03;
int padding_samples(double sample_rate) { return static_cast<int>(std::ceil(kPaddingSeconds * sample_rate)); }
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
// 3: the power factor's pivoted Cholesky by the BLAS's zgemv, the power matrix's blocks from
// their upper triangles and QQᴴ by zherk (the last bits, and so the rotated operator's, changed).
constexpr int kAnchorSolveRevision = 3;

// What one anchor gives: the transfer to the receivers, and its hat-weighted share of the power
// of the bins around it.
struct AnchorResult {
  Eigen::MatrixXcd transfer;         // R × A
  std::vector<Eigen::Index> bins;    // indices into the band's bins
  std::vector<double> power;         // W, weighted
  bool from_cache = false;
  Eigen::Index power_rank = 0;
};

// Runs task(i) for each i of `order` on `workers` threads (the calling one among them), each
// taking the next; done() after each, under a lock. The first exception stops the others and
// is rethrown here.
template <class Task, class Done>
void run_in_parallel(const std::vector<std::size_t>& order, std::size_t workers, Task&& task, Done&& done) {
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::exception_ptr failure;
  const auto work = [&] {
    for (std::size_t i = next++; i < order.size(); i = next++) {
      try {
        task(order[i]);
        const std::lock_guard lock(mutex);
        done();
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!failure) failure = std::current_exception();
        next = order.size();
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
    work();
  }
  if (failure) std::rethrow_exception(failure);
}

std::size_t workers_for(std::size_t anchors, const TyreRadiationSettings& settings) {
  return std::max<std::size_t>(1, std::min(anchors, radiation_thread_limit(settings)));
}

// The anchors, those on the finest meshes first (stable: in order within a mesh).
template <class LevelOf>
std::vector<std::size_t> costliest_first(const std::vector<double>& anchor, LevelOf&& level_of) {
  std::vector<std::size_t> order(anchor.size());
  for (std::size_t a = 0; a < anchor.size(); ++a) order[a] = a;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return level_of(anchor[x]) > level_of(anchor[y]); });
  return order;
}

// The bins (of `band`, frequency(b) in Hz) within one anchor spacing of anchor a: those whose
// power it takes a share of, by the hat function (hat()).
template <class Frequency>
std::vector<Eigen::Index> bins_of_anchor(const std::vector<double>& anchor, std::size_t a, Eigen::Index band, Frequency&& frequency) {
  const double below = a > 0 ? anchor[a - 1] : anchor[a];
  const double above = a + 1 < anchor.size() ? anchor[a + 1] : anchor[a];
  std::vector<Eigen::Index> bins;
  for (Eigen::Index b = 0; b < band; ++b)
    if (frequency(b) >= below && frequency(b) <= above && (frequency(b) > below || a == 0)) bins.push_back(b);
  return bins;
}

double hat(const std::vector<double>& anchor, std::size_t a, double f) {
  const double below = a > 0 ? anchor[a - 1] : anchor[a];
  const double above = a + 1 < anchor.size() ? anchor[a + 1] : anchor[a];
  return f < anchor[a] ? (f - below) / (anchor[a] - below) : f > anchor[a] ? (above - f) / (above - anchor[a]) : 1.0;
}

void digest_points(FnvDigest& d, const Eigen::Matrix3Xd& m) {
  d.integer(m.cols());
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < 3; ++i) d.real(m(i, j));
}

}  // namespace

std::size_t radiation_thread_limit(const TyreRadiationSettings& settings) {
  return settings.threads > 0 ? static_cast<std::size_t>(settings.threads)
                              : std::max<std::size_t>(1, std::thread::hardware_concurrency());
}

EquivalentSources make_tyre_model(const TyreSurfaceMesh& mesh, const Medium& medium, bool combined,
                                  PlaneAdmittance admittance) {
  std::optional<CombinedSources> layer;
  if (combined) layer = CombinedSources{mesh.source_normals, 1.0, kCouplingFloor};
  EquivalentSources model(mesh.sources, mesh.points, mesh.normals, true, medium, EquivalentSources::Symmetry::automatic,
                          std::move(layer));
  model.set_plane_admittance(std::move(admittance));
  return model;
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
    EquivalentSources monopoles = make_tyre_model(mesh, settings_.medium, false, settings_.admittance);
    EquivalentSources combined = make_tyre_model(mesh, settings_.medium, true, settings_.admittance);
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
  // Over an absorbing road, its admittance at the anchor (a rigid road's entries keep their
  // keys: its operators are the same to the bit). The table's and the power quadrature's
  // resolutions follow from it and the geometry, so it is all they need.
  if (settings_.admittance) {
    const std::complex<double> beta = settings_.admittance(anchor_hz);
    if (beta != 0.0) {
      d.text("impedance plane; reflected-field table and hemisphere power, revision 1");
      d.real(beta.real());
      d.real(beta.imag());
    }
  }
  return kRadiationCachePrefix + d.hex();
}

AnchorOperators TyreRadiation::solve_anchor(std::size_t level_index, double anchor_hz, Eigen::Index columns) const {
  const Level& level = levels_.at(level_index);
  const double omega = kTwoPi * anchor_hz;
  const EquivalentSources& model = anchor_hz > settings_.combined_sources_above_hz ? level.combined : level.monopoles;
  const EquivalentSourceSolve solve = model.solve(omega, settings_.regularisation);
  AnchorOperators out;
  out.transfer = solve.transfer(model.pressure_matrix(omega, receivers_)).leftCols(columns);
  // At the precision the power needs (quantised_power_operator.hpp), whether it is then stored
  // or not: a run from the cache applies the same numbers.
  QuantisedPower power = quantise_power_operator(model.power_operator(solve, omega, columns));
  out.power = std::move(power.blocks);
  out.power_quantum = power.quantum;
  return out;
}

Eigen::Index TyreRadiation::columns_of(std::size_t level, Eigen::Index active) const {
  return level + 1 == levels_.size() ? active : static_cast<Eigen::Index>(levels_[level].mesh.tread_points);
}

void TyreRadiation::for_each_anchor(const std::vector<double>& anchor, Eigen::Index active, ProgressReporter* progress,
                                    const RadiationCache* cache, std::vector<double>& seconds,
                                    const std::function<void(std::size_t, AnchorOperators&&, bool)>& use) const {
  seconds.assign(anchor.size(), 0.0);
  // This run's entries are spared by its own stores' trims until each is loaded (or solved), and
  // the folder is trimmed to its limit once all are done (radiation_cache.hpp).
  std::vector<std::string> keys;
  if (cache) {
    for (std::size_t a = 0; a < anchor.size(); ++a) {
      const std::size_t level_index = level_of(anchor[a]);
      keys.push_back(anchor_key(level_index, anchor[a], columns_of(level_index, active)));
    }
    cache->hold(keys);
  }
  struct Held {
    const RadiationCache* cache;
    ~Held() {
      if (cache) cache->release_and_trim();
    }
  } held{cache};
  const auto solve_anchor = [&](std::size_t a) {
    const auto started = std::chrono::steady_clock::now();
    struct Clock {
      std::chrono::steady_clock::time_point started;
      double& seconds;
      ~Clock() { seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); }
    } clock{started, seconds[a]};
    const std::size_t level_index = level_of(anchor[a]);
    const Level& level = levels_[level_index];
    // From the cache when it has the anchor (loaded here, in the worker, so that only the
    // anchors in hand are in memory), else solved and stored.
    const std::string key = cache ? keys[a] : std::string();
    std::optional<AnchorOperators> cached;
    const EquivalentSources& model = anchor[a] > settings_.combined_sources_above_hz ? level.combined : level.monopoles;
    if (cache)
      cached = cache->load(key, receivers_.cols(), columns_of(level_index, active),
                           model.point_coordinate_counts(columns_of(level_index, active)));
    AnchorOperators operators;
    const bool from_cache = cached.has_value();
    if (cached) {
      operators = std::move(*cached);
    } else {
      operators = this->solve_anchor(level_index, anchor[a], columns_of(level_index, active));
      if (cache) {
        const AnchorDescription description{anchor[a], level.mesh.points.cols(), level.mesh.sources.cols(), level.spec.tread_split,
                                            level.spec.sidewall_rings,
                                            anchor[a] > settings_.combined_sources_above_hz ? "combined" : "monopoles"};
        cache->store(key, operators, description);
      }
    }
    use(a, std::move(operators), from_cache);
  };
  // The costliest (finest) first, so that the threads finish together; the results go to
  // their anchors' places whatever the order.
  std::size_t finished = 0;
  run_in_parallel(costliest_first(anchor, [&](double f) { return level_of(f); }), workers_for(anchor.size(), settings_),
                  solve_anchor, [&] {
                    ++finished;
                    // May throw Interrupted (Ctrl-C): stops every worker like a failure.
                    if (progress) progress->update(finished);
                  });
}

Eigen::VectorXd TyreRadiation::power_squares(std::size_t level_index, double anchor_hz, const std::vector<Eigen::MatrixXcd>& power,
                                             const Eigen::MatrixXcd& spectra, const std::vector<Eigen::Index>& bins) const {
  const Level& level = levels_[level_index];
  const bool own = &level == &levels_.back();  // the input mesh itself
  const EquivalentSources& model = anchor_hz > settings_.combined_sources_above_hz ? level.combined : level.monopoles;
  Eigen::MatrixXcd velocities(columns_of(level_index, spectra.rows()), static_cast<Eigen::Index>(bins.size()));
  for (std::size_t i = 0; i < bins.size(); ++i) {
    const auto c = static_cast<Eigen::Index>(i);
    if (own)
      velocities.col(c) = spectra.col(bins[i]);
    else
      velocities.col(c) = level.from_input * spectra.col(bins[i]);
  }
  // W = ½ Σ_c ‖Q_c x_c‖² (EquivalentSources::power_operator).
  const std::vector<Eigen::MatrixXcd> coordinates = model.point_coordinates(velocities);
  Eigen::VectorXd squares = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(bins.size()));
  for (std::size_t c = 0; c < coordinates.size(); ++c) {
    if (power[c].rows() == 0) continue;
    const Eigen::MatrixXcd amplitudes = blas_product(power[c], coordinates[c]);
    for (Eigen::Index i = 0; i < amplitudes.cols(); ++i) squares(i) += amplitudes.col(i).squaredNorm();
  }
  return squares;
}

namespace {

void check_velocities(const TyreRadiation& radiation, Eigen::Index active, std::size_t samples, double sample_rate) {
  const TyreSurfaceMesh& input = radiation.input_mesh();
  if (active != input.tread_points && !(active == input.points.cols() && radiation.levels() == 1))
    throw std::invalid_argument(
        "tyre radiation: velocities for the tread's collocation points (or for all of them when one mesh serves every anchor)");
  if (samples < 2) throw std::invalid_argument("tyre radiation: need at least 2 samples");
  if (!(sample_rate > 0.0) || !std::isfinite(sample_rate))
    throw std::invalid_argument("tyre radiation: the sample rate must be positive");
}

}  // namespace

RadiatedSound TyreRadiation::radiate(const Eigen::MatrixXd& surface_velocity, double sample_rate,
                                     ProgressReporter* progress, const RadiationCache* cache) const {
  const Eigen::Index active = surface_velocity.cols();
  check_velocities(*this, active, static_cast<std::size_t>(surface_velocity.rows()), sample_rate);
  if (!surface_velocity.allFinite()) throw std::invalid_argument("tyre radiation: velocities must be finite");

  const std::vector<double> anchor = anchors(sample_rate);
  const Eigen::Index samples = surface_velocity.rows();
  const auto length = static_cast<int>(
      fft_friendly_size(static_cast<std::size_t>(samples) + static_cast<std::size_t>(padding_samples(sample_rate))));
  const double bin_hz = sample_rate / length;

  // Spectra of the velocities, steady part removed: for the power, of the record tapered at its
  // ends (power_taper.hpp: the run's start and the cut ends, which the microphones' and the
  // budget's estimates do not weigh, must not weigh in the power either); for the pressures, of
  // the record as it is (the convolution with the receivers' responses is linear, and its ends
  // are the record's own).
  const Eigen::VectorXd taper = power_taper(samples, padding_samples(sample_rate));
  const double taper_power = taper.squaredNorm();
  const auto first_bin = static_cast<int>(std::ceil(anchor.front() / bin_hz));
  const auto last_bin = std::min(length / 2, static_cast<int>(std::floor(anchor.back() / bin_hz)));
  const Eigen::Index band = std::max(0, last_bin - first_bin + 1);
  RealFftBatch velocity_fft(length, static_cast<int>(active));
  Eigen::MatrixXcd spectra(active, band);
  const auto transform = [&](bool tapered) {
    for (Eigen::Index m = 0; m < active; ++m) {
      const double mean = surface_velocity.col(m).mean();
      for (int n = 0; n < length; ++n)
        velocity_fft.at(static_cast<int>(m), n) =
            n < samples ? (tapered ? taper(n) : 1.0) * (surface_velocity(n, m) - mean) : 0.0;
    }
    velocity_fft.forward();
    for (Eigen::Index b = 0; b < band; ++b)
      for (Eigen::Index m = 0; m < active; ++m)
        spectra(m, b) = velocity_fft.bin(static_cast<int>(m), first_bin + static_cast<int>(b));
  };
  const auto frequency = [&](Eigen::Index b) { return (first_bin + static_cast<double>(b)) * bin_hz; };

  // Parseval for the zero-padded, tapered transform: the mean over the record of a bin's
  // harmonic power is ½qᴴSq·4/(L·Σw²) with q the sources for the bin X_k of the tapered record
  // (L the transform length; Σw² = N untapered).
  transform(true);
  const double power_scale = 4.0 / (length * taper_power);
  std::vector<AnchorResult> results(anchor.size());
  std::vector<double> seconds;
  for_each_anchor(anchor, active, progress, cache, seconds, [&](std::size_t a, AnchorOperators&& operators, bool from_cache) {
    const std::size_t level_index = level_of(anchor[a]);
    const Level& level = levels_[level_index];
    const bool own = &level == &levels_.back();  // the input mesh itself
    AnchorResult& out = results[a];
    out.from_cache = from_cache;
    out.power_rank = operators.power_rank();
    if (own)
      out.transfer = std::move(operators.transfer);
    else
      out.transfer = operators.transfer * level.from_input;
    out.bins = bins_of_anchor(anchor, a, band, frequency);
    if (out.bins.empty()) return;
    const Eigen::VectorXd squares = power_squares(level_index, anchor[a], operators.power, spectra, out.bins);
    for (std::size_t i = 0; i < out.bins.size(); ++i)
      out.power.push_back(hat(anchor, a, frequency(out.bins[i])) * power_scale * 0.5 * squares(static_cast<Eigen::Index>(i)));
  });

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

  transform(false);
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

// The stream's transform length: a fast length for FFTW of at least 8192 samples and the padding.
namespace {
constexpr std::size_t kLeastBlock = 8192;
// Points transformed at a time: their buffers (2 × 32 × L doubles, 4.4 MB at L = 8640) rather
// than one transform per point of the mesh at once (radiate()'s, 3 GB for 3000 points).
constexpr int kPointsPerTransform = 32;

int stream_length(double sample_rate) {
  if (!(sample_rate > 0.0) || !std::isfinite(sample_rate))
    throw std::invalid_argument("tyre radiation: the sample rate must be positive");
  return static_cast<int>(next_fftw_fast_length(static_cast<long>(kLeastBlock) + padding_samples(sample_rate), true));
}
}  // namespace

// What the stream keeps of each anchor: the power operator, and the block's bins it serves.
struct TyreRadiationStream::Anchor {
  std::size_t level = 0;
  std::vector<Eigen::MatrixXcd> power;
  std::vector<Eigen::Index> bins;
  std::vector<double> weight;  // per bin: the hat's share × ½
  Eigen::VectorXd squares;     // the block's Σ_c ‖Q_c x_c‖² per bin
};

std::size_t TyreRadiationStream::block_samples(double sample_rate) {
  return static_cast<std::size_t>(stream_length(sample_rate) - padding_samples(sample_rate));
}

TyreRadiationStream::TyreRadiationStream(const TyreRadiation& radiation, Eigen::Index columns, std::size_t samples,
                                         double sample_rate, ProgressReporter* progress, const RadiationCache* cache)
    : radiation_(radiation),
      columns_(columns),
      samples_(samples),
      sample_rate_(sample_rate),
      length_(stream_length(sample_rate)),
      block_(block_samples(sample_rate)),
      head_(padding_samples(sample_rate) / 4),
      velocity_fft_(length_, kPointsPerTransform),
      pressure_fft_(length_, static_cast<int>(radiation.receivers_.cols())) {
  check_velocities(radiation, columns, samples, sample_rate);
  anchor_ = radiation.anchors(sample_rate);
  const double bin_hz = sample_rate / length_;
  first_bin_ = static_cast<int>(std::ceil(anchor_.front() / bin_hz));
  const auto last_bin = std::min(length_ / 2, static_cast<int>(std::floor(anchor_.back() / bin_hz)));
  band_ = std::max(0, last_bin - first_bin_ + 1);
  const auto frequency = [&](Eigen::Index b) { return (first_bin_ + static_cast<double>(b)) * bin_hz; };

  anchors_.resize(anchor_.size());
  std::vector<Eigen::MatrixXcd> transfers(anchor_.size());
  std::vector<char> from_cache_of(anchor_.size(), 0);  // not vector<bool>: the workers write their own anchors' places
  out_.anchor_power_rank.assign(anchor_.size(), 0);
  radiation.for_each_anchor(anchor_, columns, progress, cache, out_.anchor_seconds,
                            [&](std::size_t a, AnchorOperators&& operators, bool from_cache) {
                              Anchor& kept = anchors_[a];
                              kept.level = radiation.level_of(anchor_[a]);
                              const TyreRadiation::Level& level = radiation.levels_[kept.level];
                              from_cache_of[a] = from_cache ? 1 : 0;
                              out_.anchor_power_rank[a] = operators.power_rank();
                              if (kept.level + 1 == radiation.levels_.size())
                                transfers[a] = std::move(operators.transfer);
                              else
                                transfers[a] = operators.transfer * level.from_input;
                              kept.power = std::move(operators.power);
                              kept.bins = bins_of_anchor(anchor_, a, band_, frequency);
                              for (const Eigen::Index b : kept.bins)
                                kept.weight.push_back(hat(anchor_, a, frequency(b)) * 0.5);
                              kept.squares.resize(static_cast<Eigen::Index>(kept.bins.size()));
                            });
  for (const char c : from_cache_of) out_.anchor_from_cache.push_back(c != 0);
  order_ = costliest_first(anchor_, [&](double f) { return radiation.level_of(f); });
  workers_ = workers_for(anchor_.size(), radiation.settings_);

  out_.sample_rate = sample_rate;
  out_.lowest_hz = anchor_.front();
  out_.highest_hz = anchor_.back();
  out_.delays_s = propagation_delays(radiation.receivers_, radiation.centre_, radiation.settings_.medium.sound_speed);
  out_.anchors_hz = anchor_;
  for (double f : anchor_) out_.anchor_mesh.push_back(radiation.level_of(f));
  out_.frequency_hz.resize(band_);
  for (Eigen::Index b = 0; b < band_; ++b) out_.frequency_hz(b) = frequency(b);
  out_.sound_power_w = Eigen::VectorXd::Zero(band_);
  out_.pressure = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(samples), radiation.receivers_.cols());
  table_.emplace(anchor_, std::move(transfers), out_.delays_s);

  // Everything a block needs, allocated once.
  buffer_.resize(static_cast<Eigen::Index>(std::min(block_, samples)), columns);
  spectra_.resize(columns, band_);
  transfer_.resize(radiation.receivers_.cols(), columns);
  pressure_bin_.resize(radiation.receivers_.cols());
  taper_.resize(static_cast<Eigen::Index>(buffer_.rows()));
  for (int c = 0; c < kPointsPerTransform; ++c)
    for (int n = 0; n < length_; ++n) velocity_fft_.at(c, n) = 0.0;
}

TyreRadiationStream::~TyreRadiationStream() = default;

void TyreRadiationStream::push(std::span<const double> velocity) {
  if (static_cast<Eigen::Index>(velocity.size()) != columns_)
    throw std::invalid_argument("tyre radiation stream: a sample has the wrong number of velocities");
  if (finished_ || start_ + filled_ >= samples_) throw std::logic_error("tyre radiation stream: more samples than announced");
  const auto row = static_cast<Eigen::Index>(filled_);
  for (Eigen::Index m = 0; m < columns_; ++m) {
    const double v = velocity[static_cast<std::size_t>(m)];
    if (!std::isfinite(v)) throw std::invalid_argument("tyre radiation: velocities must be finite");
    buffer_(row, m) = v;
  }
  if (++filled_ == block_) {
    apply_block(filled_);
    start_ += filled_;
    filled_ = 0;
  }
}

// The block's velocity spectra into spectra_, a few points at a time, steady part removed and,
// when `tapered`, times taper_.
void TyreRadiationStream::fill_spectra(Eigen::Index rows, bool tapered) {
  for (Eigen::Index m0 = 0; m0 < columns_; m0 += kPointsPerTransform) {
    const auto count = static_cast<int>(std::min<Eigen::Index>(kPointsPerTransform, columns_ - m0));
    for (int c = 0; c < count; ++c) {
      const Eigen::Index m = m0 + c;
      double* field = velocity_fft_.field() + static_cast<std::size_t>(c) * static_cast<std::size_t>(length_);
      if (tapered)
        for (Eigen::Index n = 0; n < rows; ++n) field[n] = taper_(n) * (buffer_(n, m) - mean_(m));
      else
        for (Eigen::Index n = 0; n < rows; ++n) field[n] = buffer_(n, m) - mean_(m);
      std::fill(field + rows, field + length_, 0.0);
    }
    velocity_fft_.forward();
    for (Eigen::Index b = 0; b < band_; ++b)
      for (int c = 0; c < count; ++c) spectra_(m0 + c, b) = velocity_fft_.bin(c, first_bin_ + static_cast<int>(b));
  }
}

void TyreRadiationStream::apply_block(std::size_t rows) {
  const auto n_rows = static_cast<Eigen::Index>(rows);
  if (!mean_known_) {
    mean_ = buffer_.topRows(n_rows).colwise().mean().transpose();
    mean_known_ = true;
  }
  // The taper of the power's spectra (power_taper.hpp): cosine ramps over the padding's length
  // at both ends (a Hann window over a block shorter than two ramps), and Σw².
  taper_ = power_taper(n_rows, padding_samples(sample_rate_));
  const double taper_power = taper_.squaredNorm();

  // The tapered spectra first, for the power in each bin, the anchors in parallel, added in
  // anchor order: the block's mean power is Σ_k ½qᴴSq·4/(L·Σw²), its share of the record's
  // N_j/N.
  fill_spectra(n_rows, true);
  run_in_parallel(order_, workers_, [&](std::size_t a) {
    Anchor& an = anchors_[a];
    if (!an.bins.empty()) an.squares = radiation_.power_squares(an.level, anchor_[a], an.power, spectra_, an.bins);
  }, [] {});
  const double block_scale = 4.0 * static_cast<double>(rows) / (static_cast<double>(samples_) * length_ * taper_power);
  for (const Anchor& an : anchors_)
    for (std::size_t i = 0; i < an.bins.size(); ++i)
      out_.sound_power_w(an.bins[i]) += block_scale * an.weight[i] * an.squares(static_cast<Eigen::Index>(i));

  // The pressures from the untapered spectra, overlap-added into the record's.
  fill_spectra(n_rows, false);
  const double bin_hz = sample_rate_ / length_;
  const int receivers = static_cast<int>(out_.pressure.cols());
  for (int r = 0; r < receivers; ++r)
    for (int k = 0; k < pressure_fft_.bins(); ++k) pressure_fft_.bin(r, k) = 0.0;
  for (Eigen::Index b = 0; b < band_; ++b) {
    table_->reduced_at((first_bin_ + static_cast<double>(b)) * bin_hz, transfer_);
    pressure_bin_.noalias() = transfer_ * spectra_.col(b);
    for (int r = 0; r < receivers; ++r) pressure_fft_.bin(r, first_bin_ + static_cast<int>(b)) = pressure_bin_(r);
  }
  pressure_fft_.backward();
  const auto start = static_cast<std::ptrdiff_t>(start_), samples = static_cast<std::ptrdiff_t>(samples_);
  for (int i = 0; i < length_; ++i) {
    // The transform's last head_ samples are lags before the block (the acausal part, wrapped round).
    const std::ptrdiff_t t = start + (i < length_ - head_ ? i : i - length_);
    if (t < 0 || t >= samples) continue;
    for (int r = 0; r < receivers; ++r) out_.pressure(t, r) += pressure_fft_.at(r, i) / length_;
  }
}

RadiatedSound TyreRadiationStream::finish() {
  if (finished_) throw std::logic_error("tyre radiation stream: finished twice");
  if (start_ + filled_ != samples_) throw std::logic_error("tyre radiation stream: fewer samples than announced");
  if (filled_ > 0) apply_block(filled_);
  finished_ = true;
  return std::move(out_);
}

}  // namespace rollnoise
