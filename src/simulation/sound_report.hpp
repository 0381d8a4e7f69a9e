#pragma once
// What `analyse` and `simulate` both write for pressure signals, computed the same way so a
// simulation and a measurement compare like for like: spectrum.csv (third-octave band levels,
// IEC 61260-1 filters, and A-weighted), the levels for summary.json (Leq, LAeq, LAFmax) and
// spectrum.png with its gnuplot script.
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "acoustics/sound_levels.hpp"
#include "core/gnuplot.hpp"

namespace rollnoise {

struct ReceiverSignal {
  std::string name;
  Eigen::VectorXd pressure;  // Pa
  double sample_rate = 0.0;  // Hz
  // The highest band to report, Hz (its centre); lower than the filters allow when the signal
  // carries nothing above some frequency (a simulation's band limit).
  double highest_band_hz = 10000.0;
};

// The band spectra (in the order of `signals`) and the levels of the signals, computed as
// write_sound_report writes them; nothing is written.
struct SoundReport {
  std::vector<BandSpectrum> spectra;
  nlohmann::json levels;  // {RECEIVER: {"Leq_dB", "LAeq_dB", "LAFmax_dB", "sample_rate_hz", "duration_s"}}
};
SoundReport sound_report(const std::vector<ReceiverSignal>& signals, const std::string& source);

// spectrum.csv (and the plot) of a report made of `signals`.
void write_sound_report(const std::filesystem::path& dir, const std::vector<ReceiverSignal>& signals,
                        const SoundReport& report, bool plot = true, PlotBatch* batch = nullptr);

// Writes spectrum.csv and the spectrum plot into `dir` and returns
// {RECEIVER: {"Leq_dB", "LAeq_dB", "LAFmax_dB", "sample_rate_hz", "duration_s"}}.
// `source` names the input in messages (InputError when a signal is too short for bands).
// `spectra` (optional) receives each signal's band spectrum, in the order of `signals`; `batch`
// (optional) draws the plot with the folder's others (core/gnuplot.hpp).
nlohmann::json write_sound_report(const std::filesystem::path& dir, const std::vector<ReceiverSignal>& signals,
                                  const std::string& source, bool plot = true,
                                  std::vector<BandSpectrum>* spectra = nullptr, PlotBatch* batch = nullptr);

}  // namespace rollnoise
