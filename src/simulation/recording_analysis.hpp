#pragma once
// A recording analysed the way a simulation's microphones are (what `rollnoise analyse` and the
// Python module's rollnoise.analyse call): a WAV file (each channel a receiver ch1, ch2, ...,
// scaled to Pa by its full scale) or the dataset 58/58b time records of sound pressure of a UFF
// file, or signals given in memory; then third-octave band levels, A-weighting, Leq, LAeq and
// LAFmax (sound_report.hpp). The result is in memory; write_recording_analysis writes
// spectrum.csv, summary.json and the plot into a folder, atomically.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "simulation/sound_report.hpp"

namespace rollnoise {

// The receivers of a recording file, in Pa. `full_scale_pa`: the pressure of WAV sample value
// 1.0; 0: the value in the WAV's comment (a WAV without one is an InputError naming
// --full-scale). `full_scale_used` receives the full scale taken (0 for UFF). A file whose name
// ends in .uff or .unv is read as UFF.
std::vector<ReceiverSignal> read_recording(const std::string& file, double full_scale_pa, double& full_scale_used);

struct RecordingAnalysis {
  std::vector<ReceiverSignal> signals;
  SoundReport report;
  nlohmann::json summary;  // what summary.json holds
};

// Reads `file` and analyses it (`full_scale_pa` as read_recording takes it).
RecordingAnalysis analyse_recording(const std::string& file, double full_scale_pa = 0.0);

// Analyses signals given in memory; `input` names them in messages and summary.json.
RecordingAnalysis analyse_signals(std::vector<ReceiverSignal> signals, const std::string& input);

// Writes spectrum.csv, summary.json and the plot into `out`, atomically.
void write_recording_analysis(const std::filesystem::path& out, const RecordingAnalysis& analysis);

}  // namespace rollnoise
