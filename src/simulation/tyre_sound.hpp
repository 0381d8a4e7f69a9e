#pragma once
// The sound of a rolling tyre run: radiation from the belt's surface velocity to the receivers
// (src/radiation), their spectra and levels (sound_report.hpp), calibrated WAV files at an audio
// rate (src/audio), a pass-by at the SPB microphone, and the radiated sound power.
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "core/cache_limit.hpp"
#include "core/gnuplot.hpp"
#include "radiation/monopole_radiation.hpp"
#include "radiation/receivers.hpp"
#include "radiation/tyre_radiation.hpp"

namespace rollnoise {

class ConfigTable;
class PointAveragedPsd;
class ProgressReporter;
class ProgressSink;
class RadiationCache;
struct TyreBudget;

struct TyreSoundSettings {
  bool enabled = true;
  TyreRadiationSettings radiation;
  // [radiation] air_pumping: the air pumped out of the contact patch radiated as monopoles at
  // its edges (contact/air_pumping.hpp, radiation/monopole_radiation.hpp), added to the
  // receivers, the sound power and the WAV files. By default on for a tyre with a tread pattern,
  // off for a slick (docs/physics/air-pumping.md, "The default").
  bool air_pumping = false;
  std::vector<Receiver> receivers;
  bool wav = true;
  double audio_rate = 48000.0;  // Hz: 48000 or 44100
  double wav_duration = 5.0;    // s, at least 5: a shorter run is looped
  // The cache of the radiation's anchor operators (radiation/radiation_cache.hpp): none, or
  // the cache folder (core/cache_folder.hpp). Not a case key: the command line chooses it.
  std::optional<std::filesystem::path> cache_folder;
  // The cache folder's size limit, kept by evicting the least recently used entries
  // (core/cache_limit.hpp): [radiation] cache_limit, which --cache-limit overrides.
  std::uint64_t cache_limit = kDefaultCacheLimitBytes;
  // Told of the radiation's progress over its anchors (core/progress.hpp); not a case key.
  ProgressSink* progress_sink = nullptr;
};

// [radiation] enabled, air_pumping (default false: docs/physics/air-pumping.md), receivers, max_frequency,
// anchor_spacing, mesh_around, mesh_across, sidewall_rings, contact_refinement, threads,
// cache_limit, geometry ("deformed": the caller sets radiation.mesh.deformation from the contact
// solution; "undeformed"); [output] wav, audio_rate, wav_duration. The tyre's radius and width (m) shape the radiating body.
// `default_max_frequency` (Hz): max_frequency when the case does not give it (the upper edge of
// the [rolling] band_top band). Bad values are InputErrors naming the key.
TyreSoundSettings read_tyre_sound_settings(const ConfigTable& radiation, const ConfigTable& output, double radius,
                                           double width, double default_max_frequency = 5623.4);

// Empty when every receiver is outside the radiating body of `settings` (the deformed tyre once
// its patch is set); otherwise the message naming the first inside it.
std::string receivers_outside_tyre(const TyreSoundSettings& settings);

// Writes spectrum.csv, sound_power.csv, <receiver>.wav (and spb_passby.wav with an spb
// receiver) and their plots into `dir`; returns the summary entries ("levels", "full_scale_pa",
// "sound_power", "radiation"); the plots go to `plots` (none when null). tread_velocity: samples × tread points of the radiation mesh
// (outward normal velocity, m/s) at `sample_rate`; speed in m/s. With a `budget` (the contact and
// response lines of the run), also budget.csv and its plot (energy_budget_output.hpp) and the
// summary entry "energy_budget". progress: a progress bar over the anchors on a terminal.
// air_pumping: the monopoles of the air pumped out of the patch, sampled as the velocity
// (none: no air pumping); their pressure is added to the receivers' and their power to the
// sound power, and the summary gains "air_pumping" (and budget.csv its line).
nlohmann::json write_tyre_sound(const std::filesystem::path& dir, const TyreSoundSettings& settings,
                                const Eigen::MatrixXd& tread_velocity, double sample_rate, double speed,
                                const std::string& source, PlotBatch* plots, const TyreBudget* budget = nullptr,
                                bool progress = true, const MonopoleSources* air_pumping = nullptr);

// The radiation stage fed the tread velocity sample by sample as the run makes it, for a run too
// long to keep the whole record (issue 13: samples × tread points in doubles, 3 GB for 10 s at
// 80 km/h on the 5 kHz grid). The first push() makes the radiating body's mesh from the
// settings (the caller has set its deformation by then: the run's mean contact patch) and solves
// or loads the anchors' operators (radiation/tyre_radiation.hpp, TyreRadiationStream); the
// samples are then transformed and applied in blocks, and the energy budget's PSD of the
// radiating velocity takes them one by one. `settings` must outlive the stream.
class TyreSoundStream {
 public:
  // Whether a run of `samples` at `sample_rate` goes through a stream: more samples than one
  // block. A run within one block keeps its record and takes the whole-record transform, so its
  // numbers stay what they were before the stream, bit for bit.
  static bool wanted(std::size_t samples, double sample_rate);

  // budget_segment: the Welch segment of the energy budget (0: no budget, no PSD). progress:
  // a progress bar over the anchors on a terminal (between the run's own bar's updates).
  TyreSoundStream(const TyreSoundSettings& settings, std::size_t samples, double sample_rate, std::size_t budget_segment,
                  std::string source, bool progress);
  ~TyreSoundStream();
  TyreSoundStream(const TyreSoundStream&) = delete;
  TyreSoundStream& operator=(const TyreSoundStream&) = delete;

  // The next sample: the tread velocity on the radiation's input mesh (its tread points).
  void push(std::span<const double> tread_velocity);

 private:
  friend nlohmann::json write_tyre_sound(const std::filesystem::path&, const TyreSoundSettings&, TyreSoundStream&, double,
                                         const std::string&, PlotBatch*, const TyreBudget*, const MonopoleSources*);
  const TyreSoundSettings& settings_;
  std::size_t samples_;
  double sample_rate_;
  std::size_t budget_segment_;
  std::string source_;
  bool progress_;
  std::unique_ptr<TyreRadiation> radiation_;
  std::unique_ptr<RadiationCache> cache_;
  std::unique_ptr<TyreRadiationStream> stream_;
  std::unique_ptr<PointAveragedPsd> radiating_;
  std::chrono::steady_clock::duration busy_{};  // in push(): the stage's time
};

// write_tyre_sound for a run whose tread velocity went through `stream` (all its samples
// pushed): the same outputs.
nlohmann::json write_tyre_sound(const std::filesystem::path& dir, const TyreSoundSettings& settings, TyreSoundStream& stream,
                                double speed, const std::string& source, PlotBatch* plots, const TyreBudget* budget = nullptr,
                                const MonopoleSources* air_pumping = nullptr);

}  // namespace rollnoise
