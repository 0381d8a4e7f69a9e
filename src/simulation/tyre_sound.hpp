#pragma once
// The sound of a rolling tyre run: radiation from the belt's surface velocity to the receivers
// (src/radiation), their spectra and levels (sound_report.hpp), calibrated WAV files at an audio
// rate (src/audio), a pass-by at the SPB microphone, and the radiated sound power.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "radiation/receivers.hpp"
#include "radiation/tyre_radiation.hpp"

namespace rollnoise {

class ConfigTable;
struct TyreBudget;

struct TyreSoundSettings {
  bool enabled = true;
  TyreRadiationSettings radiation;
  std::vector<Receiver> receivers;
  bool wav = true;
  double audio_rate = 48000.0;  // Hz: 48000 or 44100
  double wav_duration = 5.0;    // s, at least 5: a shorter run is looped
  // The cache of the radiation's anchor operators (radiation/radiation_cache.hpp): none, or
  // the cache folder (core/cache_folder.hpp). Not a case key: the command line chooses it.
  std::optional<std::filesystem::path> cache_folder;
};

// [radiation] enabled, receivers, max_frequency, anchor_spacing, mesh_around, mesh_across,
// sidewall_rings, contact_refinement, threads, geometry ("deformed": the caller sets
// radiation.mesh.deformation from the contact solution; "undeformed"); [output] wav, audio_rate,
// wav_duration. The tyre's radius and width (m) shape the radiating body.
// `default_max_frequency` (Hz): max_frequency when the case does not give it (the upper edge of
// the [rolling] band_top band). Bad values are InputErrors naming the key.
TyreSoundSettings read_tyre_sound_settings(const ConfigTable& radiation, const ConfigTable& output, double radius,
                                           double width, double default_max_frequency = 5623.4);

// Empty when every receiver is outside the radiating body of `settings` (the deformed tyre once
// its patch is set); otherwise the message naming the first inside it.
std::string receivers_outside_tyre(const TyreSoundSettings& settings);

// Writes spectrum.csv, sound_power.csv, <receiver>.wav (and spb_passby.wav with an spb
// receiver) and their plots into `dir`; returns the summary entries ("levels", "full_scale_pa",
// "sound_power", "radiation"). tread_velocity: samples × tread points of the radiation mesh
// (outward normal velocity, m/s) at `sample_rate`; speed in m/s. With a `budget` (the contact and
// response lines of the run), also budget.csv and its plot (energy_budget_output.hpp) and the
// summary entry "energy_budget". progress: a progress bar over the anchors on a terminal.
nlohmann::json write_tyre_sound(const std::filesystem::path& dir, const TyreSoundSettings& settings,
                                const Eigen::MatrixXd& tread_velocity, double sample_rate, double speed,
                                const std::string& source, bool plots, const TyreBudget* budget = nullptr,
                                bool progress = true);

}  // namespace rollnoise
