#include "simulation/tyre_sound.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "acoustics/band_power.hpp"
#include "acoustics/fractional_octave_bands.hpp"
#include "acoustics/frequency_weighting.hpp"
#include "audio/pass_by.hpp"
#include "audio/resampler.hpp"
#include "audio/seamless_loop.hpp"
#include "audio/wav_file.hpp"
#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/output_directory.hpp"
#include "core/byte_size.hpp"
#include "core/gnuplot.hpp"
#include "core/progress.hpp"
#include "radiation/impedance_plane_green.hpp"
#include "radiation/monopole_radiation.hpp"
#include "radiation/radiation_cache.hpp"
#include "simulation/energy_budget_output.hpp"
#include "simulation/sound_report.hpp"
#include "simulation/stage_times.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

// Band sound power levels from the power in each transform bin: the bins within each band's
// exact edges (IEC 61260-1), L_W re 1 pW, and A-weighted at the exact mid-band frequency.
nlohmann::json write_sound_power(const fs::path& dir, const RadiatedSound& sound, double highest_band_hz, PlotBatch* plots) {
  const std::vector<FractionalOctaveBand> bands = fractional_octave_bands(3, 20.0, highest_band_hz);
  std::ofstream out(dir / "sound_power.csv", std::ios::binary);
  CsvWriter csv(out, {"band_hz", "Lw_dB", "LwA_dB"});
  double total = 0.0, total_a = 0.0;
  const std::vector<double> powers =
      band_sums(std::span<const double>(sound.frequency_hz.data(), static_cast<std::size_t>(sound.frequency_hz.size())),
                std::span<const double>(sound.sound_power_w.data(), static_cast<std::size_t>(sound.sound_power_w.size())),
                bands);
  for (std::size_t b = 0; b < bands.size(); ++b) {
    const FractionalOctaveBand& band = bands[b];
    const double power = powers[b];
    const double a = weighting_db(FrequencyWeighting::A, band.exact);
    const double lw = 10.0 * std::log10(std::max(power, 1e-30) / 1e-12);
    total += power;
    total_a += power * std::pow(10.0, a / 10.0);
    const double row[] = {band.nominal, lw, lw + a};
    csv.row(row, 3);
  }
  close_output_file(out, dir / "sound_power.csv");
  if (plots) {
    std::ostringstream gp;
    gp << "# Drawn by rollnoise from sound_power.csv; run `gnuplot sound_power.gp` to redraw.\n"
       << "set terminal pngcairo size 1000,550 noenhanced font 'DejaVu Sans,10'\n"
       << "set output 'sound_power.png'\nset datafile separator ','\nset grid\nset logscale x\n"
       << "set xlabel 'third-octave band (Hz)'\nset ylabel 'sound power level (dB re 1 pW)'\nset key top left\n"
       << "set title 'Sound power radiated by the tyre (into the half-space above the road)'\n"
       << "plot 'sound_power.csv' skip 1 using 1:2 with linespoints lw 1.5 pt 7 ps 0.6 title 'L_W', \\\n"
       << "     '' skip 1 using 1:3 with linespoints lw 1.5 pt 5 ps 0.6 title 'L_WA'\n";
    write_plot(dir, "sound_power", gp.str(), plots);
  }
  return {{"Lw_dB", 10.0 * std::log10(std::max(total, 1e-30) / 1e-12)},
          {"LwA_dB", 10.0 * std::log10(std::max(total_a, 1e-30) / 1e-12)},
          {"total_W", total}};
}

}  // namespace

TyreSoundSettings read_tyre_sound_settings(const ConfigTable& radiation, const ConfigTable& output, double radius,
                                           double width, double default_max_frequency) {
  TyreSoundSettings s;
  s.enabled = radiation.boolean("enabled", true);
  // Off unless asked: its 2–4 kHz octaves are not yet converged in the grid and come out far above
  // measured spectra (docs/physics/air-pumping.md, "The default").
  s.air_pumping = radiation.boolean("air_pumping", false);
  s.receivers = read_receivers(radiation, width);
  s.radiation.mesh.radius = radius;
  s.radiation.mesh.width = width;
  s.radiation.max_frequency_hz = radiation.between("max_frequency", 20.0, 20000.0, default_max_frequency);
  s.radiation.anchor_spacing_hz = radiation.between("anchor_spacing", 4.999, 1000.001, 100.0);
  // The default mesh resolves the horn between tread and road (tests/radiation/test_horn_effect.cpp):
  // 2 mm cells at the contact growing to 2.1 cm, 16 rows across (1.1 cm), 12 rings per sidewall.
  s.radiation.mesh.around = static_cast<int>(radiation.integer("mesh_around", 96, 8, 1024));
  s.radiation.mesh.across = static_cast<int>(radiation.integer("mesh_across", 16, 1, 128));
  s.radiation.mesh.sidewall_rings = static_cast<int>(radiation.integer("sidewall_rings", 12, 1, 256));
  s.radiation.mesh.contact_refinement = radiation.between("contact_refinement", 0.999, 1000.001, 10.0);
  s.radiation.threads = static_cast<int>(radiation.integer("threads", 0, 0, 1024));
  // The cache folder's size limit (core/cache_limit.hpp); --cache-limit overrides it.
  if (const std::string limit_text = radiation.text("cache_limit", ""); !limit_text.empty()) {
    const std::optional<std::uint64_t> limit = parse_byte_size(limit_text);
    if (!limit) radiation.fail("cache_limit", std::string("must be ") + kByteSizeForms + " (got \"" + limit_text + "\")");
    s.cache_limit = *limit;
  }
  // Finer meshes for the upper anchors (tyre_radiation.hpp): the tread split in 2 (4, …) above
  // c/(n·2πR/mesh_around); 0: the mesh above for every anchor.
  s.radiation.points_per_wavelength = radiation.between("points_per_wavelength", -0.001, 20.0, 4.0);
  // The anchors above this take combined sources (equivalent_sources.hpp), those at or below
  // monopoles (0: combined sources for every anchor).
  s.radiation.combined_sources_above_hz = radiation.between("combined_sources_above", -0.001, 1e6, kCombinedSourcesAboveHz);
  if (s.radiation.points_per_wavelength < 2.0 && s.radiation.points_per_wavelength != 0.0)
    radiation.fail("points_per_wavelength", "must be 0 (one mesh) or at least 2");
  // The radiating body: the loaded tyre, flattened over the run's mean contact patch (the
  // caller fills in the patch and the indentation once the contact is solved), or the
  // undeformed cylinder of earlier versions.
  s.radiation.mesh.geometry = radiation.choice("geometry", {"deformed", "undeformed"}, "deformed") == "deformed"
                                  ? TyreGeometry::deformed
                                  : TyreGeometry::undeformed;
  radiation.reject_unknown_keys();
  for (const Receiver& r : s.receivers) {
    if (r.name == "spb_passby")
      radiation.fail("receivers", "\"spb_passby\" is the name of the pass-by at the spb microphone; choose another name");
    // The body: a cylinder of the tyre's radius on the axle (mesh coordinates). The deformed
    // tyre is checked again once its shape is known (receivers_outside_tyre).
    const double axle = radius + s.radiation.mesh.clearance;
    const double from_axis = std::hypot(r.position.x(), r.position.z() - axle);
    if (from_axis <= radius && std::abs(r.position.y()) <= 0.5 * width)
      radiation.fail("receivers", "\"" + r.name + "\" is inside the tyre; receivers must be outside it");
  }
  s.wav = output.boolean("wav", true);
  const std::int64_t rate = output.integer("audio_rate", 48000, 1, 1000000);
  if (rate != 48000 && rate != 44100) output.fail("audio_rate", "must be 48000 or 44100 (Hz)");
  s.audio_rate = static_cast<double>(rate);
  s.wav_duration = output.between("wav_duration", 4.999, 3600.0, 5.0);
  return s;
}

std::string receivers_outside_tyre(const TyreSoundSettings& settings) {
  const TyreSurfaceShape shape(settings.radiation.mesh);
  const double axle = shape.axle_height();
  for (const Receiver& r : settings.receivers) {
    if (std::abs(r.position.y()) > 0.5 * settings.radiation.mesh.width) continue;
    const double polar = std::atan2(r.position.x(), axle - r.position.z());
    const double from_axis = std::hypot(r.position.x(), r.position.z() - axle);
    if (from_axis <= shape.radius(shape.material_angle(polar), r.position.y()) || r.position.z() <= 0.0)
      return "\"" + r.name + "\" is inside the loaded tyre; receivers must be outside it";
  }
  return {};
}

namespace {

std::unique_ptr<TyreRadiation> make_radiation(const TyreSoundSettings& settings) {
  Eigen::Matrix3Xd positions(3, static_cast<Eigen::Index>(settings.receivers.size()));
  for (std::size_t r = 0; r < settings.receivers.size(); ++r)
    positions.col(static_cast<Eigen::Index>(r)) = settings.receivers[r].position;
  return std::make_unique<TyreRadiation>(settings.radiation, positions);
}

// summary.json's "air_pumping": the sources, their power over the band and per octave (500 Hz to
// 4 kHz, where the air pumping is compared with measurements), beside the vibration's.
nlohmann::json air_pumping_summary(const MonopoleSources& sources, const MonopoleSound& air, const RadiatedSound& vibration,
                                   double highest_band_hz) {
  const auto level = [](double w) { return 10.0 * std::log10(std::max(w, 1e-30) / 1e-12); };
  const std::span<const double> f(vibration.frequency_hz.data(), static_cast<std::size_t>(vibration.frequency_hz.size()));
  const std::vector<FractionalOctaveBand> octaves = fractional_octave_bands(1, 500.0, std::min(4000.0, highest_band_hz));
  const std::vector<double> air_bands =
      band_sums(f, std::span<const double>(air.sound_power_w.data(), static_cast<std::size_t>(air.sound_power_w.size())), octaves);
  const std::vector<double> vibration_bands = band_sums(
      f, std::span<const double>(vibration.sound_power_w.data(), static_cast<std::size_t>(vibration.sound_power_w.size())),
      octaves);
  nlohmann::json bands = nlohmann::json::array();
  for (std::size_t b = 0; b < octaves.size(); ++b)
    bands.push_back({{"band_hz", octaves[b].nominal},
                     {"Lw_air_pumping_dB", level(air_bands[b])},
                     {"Lw_vibration_dB", level(vibration_bands[b])}});
  nlohmann::json positions = nlohmann::json::array();
  for (Eigen::Index s = 0; s < sources.positions.cols(); ++s)
    positions.push_back({sources.positions(0, s), sources.positions(1, s), sources.positions(2, s)});
  double rms = 0.0;
  for (Eigen::Index s = 0; s < sources.flows.cols(); ++s) {
    const Eigen::ArrayXd fluctuation = sources.flows.col(s).array() - sources.flows.col(s).mean();
    rms = std::max(rms, std::sqrt(fluctuation.square().mean()));
  }
  return {{"Lw_dB", level(air.total_power_w)},
          {"total_W", air.total_power_w},
          {"source_positions_m", positions},
          {"largest_rms_flow_m3_per_s", rms},
          {"octaves", bands}};
}

// The outputs from the radiation stage's results, whichever way it ran. radiating: the PSD of the
// radiating velocity (with a budget); radiation_seconds: the stage's time.
nlohmann::json write_radiated_sound(const fs::path& dir, const TyreSoundSettings& settings, const TyreRadiation& radiation,
                                    const RadiatedSound& vibration, const PointAveragedPsd* radiating, double radiation_seconds,
                                    double sample_rate, double speed, const std::string& source, PlotBatch* plots,
                                    const TyreBudget* budget, const MonopoleSources* air_pumping, StageTimes& stages) {
  // Bands whose upper edge the radiation reaches: centre at most the top frequency / 2^(1/6).
  const double highest_band = vibration.highest_hz / std::pow(2.0, 1.0 / 6.0);
  // The air pumped out of the patch, through the same road as the vibration, added to the
  // vibration's pressure and power: what the receivers hear and the WAV files hold is the sum.
  std::optional<MonopoleSound> air;
  RadiatedSound with_air;
  if (air_pumping) {
    Eigen::Matrix3Xd positions(3, static_cast<Eigen::Index>(settings.receivers.size()));
    for (std::size_t r = 0; r < settings.receivers.size(); ++r)
      positions.col(static_cast<Eigen::Index>(r)) = settings.receivers[r].position;
    air = radiate_monopoles(*air_pumping, sample_rate, positions, vibration.delays_s, vibration.lowest_hz,
                            vibration.highest_hz, vibration.frequency_hz, settings.radiation.medium, rigid_road_green());
    with_air = vibration;
    with_air.pressure += air->pressure;
    with_air.sound_power_w += air->sound_power_w;
    stages.lap("air_pumping");
  }
  const RadiatedSound& sound = air ? with_air : vibration;

  // Each receiver at the audio rate, looped (without clicks) to the WAV's length.
  std::vector<ReceiverSignal> signals;
  for (std::size_t r = 0; r < settings.receivers.size(); ++r) {
    const Eigen::VectorXd at_audio_rate =
        resample(sound.pressure.col(static_cast<Eigen::Index>(r)), sample_rate, settings.audio_rate);
    signals.push_back({settings.receivers[r].name,
                       loop_to_duration(at_audio_rate, settings.audio_rate, settings.wav_duration), settings.audio_rate,
                       highest_band});
  }
  // The pass-by at the SPB microphone (ISO 11819-1), from the stationary spb signal.
  const auto spb = std::find_if(settings.receivers.begin(), settings.receivers.end(),
                                [](const Receiver& r) { return r.name == "spb"; });
  if (spb != settings.receivers.end()) {
    PassBySettings passing;
    passing.speed = speed;
    passing.receiver_distance = spb->position.y();
    passing.receiver_height = spb->position.z();
    passing.duration = settings.wav_duration;
    passing.sound_speed = settings.radiation.medium.sound_speed;
    // Over an absorbing road the image path carries the impedance plane's reflection at the
    // tyre's horizontal distance as it passes (pass_by.hpp), from the exact field.
    if (settings.radiation.admittance)
      passing.ground_reflection_factor = [admittance = settings.radiation.admittance, passing](double frequency,
                                                                                               double distance) {
        const double k = 2.0 * std::numbers::pi * frequency / passing.sound_speed;
        const double height = passing.receiver_height + passing.source_height;
        const double r2 = std::hypot(distance, height);
        const std::complex<double> image = std::polar(1.0 / (4.0 * std::numbers::pi * r2), -k * r2);
        // (to 1e-10 of the image's field: the filter's series holds Q to 1e-4)
        return 1.0 + impedance_plane_correction(k, distance, height, admittance(frequency), 1e-10) / image;
      };
    const ReceiverSignal& stationary = signals[static_cast<std::size_t>(spb - settings.receivers.begin())];
    signals.push_back({"spb_passby", pass_by(make_loopable(stationary.pressure, settings.audio_rate), settings.audio_rate, passing),
                       settings.audio_rate, highest_band});
  }
  stages.lap("audio_signals");
  nlohmann::json result;
  std::vector<BandSpectrum> spectra;
  result["levels"] = write_sound_report(dir, signals, source, plots != nullptr, &spectra, plots);
  stages.lap("spectra_and_levels");
  result["sound_power"] = write_sound_power(dir, sound, highest_band, plots);
  stages.lap("sound_power");
  if (budget) {
    if (!radiating) throw std::logic_error("write_tyre_sound: a budget without the radiating velocity's PSD");
    result["energy_budget"] = write_energy_budget(dir, *budget, vibration, *radiating, radiation.mesh(),
                                                  settings.radiation.mesh.radius, settings.radiation.medium,
                                                  settings.receivers, spectra, plots, air ? &air->sound_power_w : nullptr);
    stages.lap("energy_budget_output");
  }

  double peak = 0.0;
  for (const ReceiverSignal& s : signals) peak = std::max(peak, s.pressure.cwiseAbs().maxCoeff());
  const double full_scale = round_full_scale(peak);
  if (settings.wav) {
    for (const ReceiverSignal& s : signals) {
      WavWriteOptions options;
      options.full_scale_pa = full_scale;
      options.title = s.name;
      write_wav(dir / (s.name + ".wav"), s.pressure, settings.audio_rate, options);
    }
    result["full_scale_pa"] = full_scale;
    result["audio_rate_hz"] = settings.audio_rate;
    result["wav_duration_s"] = static_cast<double>(signals.front().pressure.size()) / settings.audio_rate;
    stages.lap("wav");
  }
  // The mesh's flat: the extent of its vertices on the road (at the clearance), to compare with
  // the contact solution's patch_length_m and patch_width_m.
  double flat_x0 = 0.0, flat_x1 = 0.0, flat_y0 = 0.0, flat_y1 = 0.0;
  bool flat = false;
  const TyreSurfaceMesh& mesh = radiation.mesh();
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    if (settings.radiation.mesh.geometry != TyreGeometry::deformed ||
        mesh.vertices(2, v) > settings.radiation.mesh.clearance * (1.0 + 1e-9))
      continue;
    const double x = mesh.vertices(0, v), y = mesh.vertices(1, v);
    flat_x0 = flat ? std::min(flat_x0, x) : x;
    flat_x1 = flat ? std::max(flat_x1, x) : x;
    flat_y0 = flat ? std::min(flat_y0, y) : y;
    flat_y1 = flat ? std::max(flat_y1, y) : y;
    flat = true;
  }
  // The meshes per band (coarse to fine; the last is the one the velocities come in on).
  nlohmann::json meshes = nlohmann::json::array();
  for (std::size_t l = 0; l < radiation.levels(); ++l) {
    std::size_t anchors = 0, from_cache = 0;
    double seconds = 0.0;
    Eigen::Index rank = 0;
    for (std::size_t a = 0; a < sound.anchor_mesh.size(); ++a)
      if (sound.anchor_mesh[a] == l) {
        ++anchors;
        seconds += sound.anchor_seconds[a];
        from_cache += sound.anchor_from_cache[a] ? 1 : 0;
        rank = std::max(rank, sound.anchor_power_rank[a]);
      }
    meshes.push_back({{"collocation_points", radiation.level_mesh(l).points.cols()},
                      {"equivalent_sources", radiation.level_mesh(l).sources.cols()},
                      {"tread_split", radiation.level_spec(l).tread_split},
                      {"sidewall_rings", radiation.level_spec(l).sidewall_rings},
                      {"up_to_hz", radiation.level_top_hz(l)},
                      {"anchors", anchors},
                      {"anchors_from_cache", from_cache},
                      {"largest_power_rank", rank},  // rows of the power operator (radiation_cache.hpp)
                      {"anchor_time_s", seconds}});  // summed over the anchors, each in its thread
  }
  const bool deformed = settings.radiation.mesh.geometry == TyreGeometry::deformed;
  result["radiation"] = {{"band_hz", {sound.lowest_hz, sound.highest_hz}},
                         // The patch the body is flattened over (the run's mean contact patch,
                         // tyre_simulation.cpp): what the radiation cache's key covers.
                         {"patch_length_m", deformed ? settings.radiation.mesh.deformation.patch_length : 0.0},
                         {"patch_width_m", deformed ? settings.radiation.mesh.deformation.patch_width : 0.0},
                         {"flat_length_m", flat_x1 - flat_x0},
                         {"flat_width_m", flat_y1 - flat_y0},
                         {"anchors", radiation.anchors(sample_rate).size()},
                         {"collocation_points", radiation.mesh().points.cols()},
                         {"equivalent_sources", radiation.mesh().sources.cols()},
                         {"meshes", meshes},
                         {"geometry", settings.radiation.mesh.geometry == TyreGeometry::deformed ? "deformed" : "undeformed"},
                         {"axle_height_m", radiation.mesh().axle_height},
                         {"anchors_from_cache", std::count(sound.anchor_from_cache.begin(), sound.anchor_from_cache.end(), true)},
                         {"cache", settings.cache_folder ? settings.cache_folder->string() : std::string()},
                         // The threads the anchors were solved on, at most ([radiation] threads, or
                         // what the study gave this case, else one per core).
                         {"threads", radiation_thread_limit(settings.radiation)},
                         // The plane the sources see: the rigid road, or the impedance plane of
                         // the road's [road.absorption] (docs/physics/absorbing-roads.md).
                         {"road", settings.radiation.admittance ? "impedance plane" : "rigid"},
                         {"time_s", radiation_seconds}};
  if (air) result["air_pumping"] = air_pumping_summary(*air_pumping, *air, vibration, highest_band);
  stages.lap("sound_summary");
  result["sound_stage_times_s"] = stages.json();  // tyre_simulation.cpp folds it into stage_times_s
  return result;
}

}  // namespace

nlohmann::json write_tyre_sound(const fs::path& dir, const TyreSoundSettings& settings,
                                const Eigen::MatrixXd& tread_velocity, double sample_rate, double speed,
                                const std::string& source, PlotBatch* plots, const TyreBudget* budget, bool progress,
                                const MonopoleSources* air_pumping) {
  const auto started = std::chrono::steady_clock::now();
  StageTimes stages;
  const std::unique_ptr<TyreRadiation> radiation = make_radiation(settings);
  // Always there, drawn only when asked: its updates poll Ctrl-C also in a study's quiet cases.
  ProgressReporter bar("radiation " + source, radiation->anchors(sample_rate).size(), {}, progress,
                       settings.progress_sink);
  std::optional<RadiationCache> cache;
  if (settings.cache_folder) cache.emplace(*settings.cache_folder, settings.cache_limit);
  const RadiatedSound sound = radiation->radiate(tread_velocity, sample_rate, &bar, cache ? &*cache : nullptr);
  bar.finish();
  const double radiation_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  stages.lap("radiation");
  std::unique_ptr<PointAveragedPsd> radiating;
  if (budget) {
    radiating = radiating_velocity_psd(radiation->mesh(), budget->sample_rate, budget->segment_length);
    std::vector<double> row(static_cast<std::size_t>(tread_velocity.cols()));
    for (Eigen::Index n = 0; n < tread_velocity.rows(); ++n) {
      for (std::size_t p = 0; p < row.size(); ++p) row[p] = tread_velocity(n, static_cast<Eigen::Index>(p));
      radiating->push(row);
    }
    stages.lap("energy_budget_output");
  }
  return write_radiated_sound(dir, settings, *radiation, sound, radiating.get(), radiation_seconds, sample_rate, speed, source,
                              plots, budget, air_pumping, stages);
}

bool TyreSoundStream::wanted(std::size_t samples, double sample_rate) {
  return samples > TyreRadiationStream::block_samples(sample_rate);
}

TyreSoundStream::TyreSoundStream(const TyreSoundSettings& settings, std::size_t samples, double sample_rate,
                                 std::size_t budget_segment, std::string source, bool progress)
    : settings_(settings),
      samples_(samples),
      sample_rate_(sample_rate),
      budget_segment_(budget_segment),
      source_(std::move(source)),
      progress_(progress) {}

TyreSoundStream::~TyreSoundStream() = default;

void TyreSoundStream::push(std::span<const double> tread_velocity) {
  const auto started = std::chrono::steady_clock::now();
  if (!stream_) {
    // The first sample: the radiating body is known (the caller set the settings' deformation).
    radiation_ = make_radiation(settings_);
    if (settings_.cache_folder) cache_ = std::make_unique<RadiationCache>(*settings_.cache_folder, settings_.cache_limit);
    ProgressReporter bar("radiation " + source_, radiation_->anchors(sample_rate_).size(), {}, progress_,
                         settings_.progress_sink);
    stream_ = std::make_unique<TyreRadiationStream>(*radiation_, static_cast<Eigen::Index>(tread_velocity.size()), samples_,
                                                    sample_rate_, &bar, cache_.get());
    bar.finish();
    if (budget_segment_ > 0) radiating_ = radiating_velocity_psd(radiation_->mesh(), sample_rate_, budget_segment_);
  }
  stream_->push(tread_velocity);
  if (radiating_) radiating_->push(tread_velocity);
  busy_ += std::chrono::steady_clock::now() - started;
}

nlohmann::json write_tyre_sound(const fs::path& dir, const TyreSoundSettings& settings, TyreSoundStream& stream, double speed,
                                const std::string& source, PlotBatch* plots, const TyreBudget* budget,
                                const MonopoleSources* air_pumping) {
  if (!stream.stream_) throw std::logic_error("write_tyre_sound: nothing was pushed to the radiation stream");
  const auto started = std::chrono::steady_clock::now();
  StageTimes stages;
  const RadiatedSound sound = stream.stream_->finish();  // the last block
  stages.lap("radiation");
  // The stage ran while the run went: its time is that of the pushes and of the last block.
  const double radiation_seconds =
      std::chrono::duration<double>(stream.busy_ + (std::chrono::steady_clock::now() - started)).count();
  if (budget && budget->segment_length != stream.budget_segment_)
    throw std::logic_error("write_tyre_sound: the budget's Welch segment is not the stream's");
  return write_radiated_sound(dir, settings, *stream.radiation_, sound, stream.radiating_.get(), radiation_seconds,
                              stream.sample_rate_, speed, source, plots, budget, air_pumping, stages);
}

}  // namespace rollnoise
