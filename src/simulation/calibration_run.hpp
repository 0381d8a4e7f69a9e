#pragma once
// A tyre model fitted to measured mobilities (what `rollnoise calibrate` and the Python module's
// rollnoise.calibrate call): the data files read (CSV or UFF 58/58b, positions from the files,
// the nodes, the response and excitation points), the model built for the band, the Ceres fit
// (calibrate/calibration.hpp), the calibrated model file and the report. The result is in
// memory; write_calibration_outputs writes calibrated.toml, fit.csv, report.json and fit.png into
// a folder, atomically.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibrate/calibration.hpp"
#include "calibrate/measured_frf.hpp"

namespace rollnoise {

class ProgressSink;

// The command line's options, in its words: positions as "X,Y", nodes as "N=X,Y", the band as
// "LO:HI" (messages name the options: --response, --node, --frequency-range, --data-type).
struct CalibrationRunOptions {
  std::string model;                    // the model file
  std::vector<std::string> data;        // the data files
  std::vector<std::string> fit;         // the free parameters; empty: the model's default
  std::string data_type = "mobility";   // mobility, receptance or accelerance
  bool data_type_given = false;         // a file that says otherwise is then an error
  std::vector<std::string> response;    // "X,Y": once for every FRF without its own, or once per file
  std::vector<std::string> excitation;
  std::vector<std::string> nodes;       // "N=X,Y": positions of UFF nodes
  double transducer_mass = 0.0;         // kg
  std::string frequency_range;          // "LO:HI" in Hz; empty: the model's valid range
  int starts = 0;                       // 0: the model's choice
  std::uint64_t seed = 1;
  double loss_scale = 0.25;
  double first_stage = -1.0;            // Hz; < 0: the model's choice, 0: none
  bool force = false;                   // run even when the estimate exceeds the machine
  bool progress = true;                 // a progress bar on a terminal
  ProgressSink* progress_sink = nullptr;
  // Told of what a reader left out or assumed, as the data are read (the command line prints
  // "rollnoise: note: ..."); none: kept in CalibrationRun::notes only.
  std::function<void(const std::string&)> note;
};

struct CalibrationRun {
  std::vector<std::string> notes;
  std::vector<MeasuredFrf> data;
  CalibrationResult result;
  std::string calibrated;  // calibrated.toml
  nlohmann::json report;   // report.json
};

// Reads the data and fits. Bad input is an InputError. `out`: where the outputs will go, for the
// size estimate (empty: the current folder).
CalibrationRun run_calibration(const CalibrationRunOptions& options, const std::filesystem::path& out = {});

// Writes calibrated.toml, fit.csv, report.json and fit.png into `out`, atomically.
void write_calibration_outputs(const std::filesystem::path& out, const CalibrationRun& run);

}  // namespace rollnoise
