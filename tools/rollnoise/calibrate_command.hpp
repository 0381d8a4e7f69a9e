#pragma once
// `rollnoise calibrate MODEL.toml --data FILE... [--fit p1,p2,...] [--out DIR]`: fits the
// model's parameters to measured mobilities (CSV or UFF 58/58b) and writes calibrated.toml (a
// model file `simulate` takes), fit.csv, report.json and fit.png (MODEL.md §6).
#include <cstdint>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rollnoise {

struct CalibrateOptions {
  std::string model;
  std::vector<std::string> data;
  std::vector<std::string> fit;
  std::string out;
  std::string data_type = "mobility";
  std::vector<std::string> response;    // "X,Y": one for every FRF without its own, or one per data file
  std::vector<std::string> excitation;
  std::vector<std::string> nodes;       // "N=X,Y": positions of UFF nodes
  double transducer_mass = 0.0;
  std::string frequency_range;          // "LO:HI" in Hz
  int starts = 0;  // 0: the model's choice (8; 1 for two_layer)
  std::uint64_t seed = 1;
  double loss_scale = 0.25;
  double first_stage = -1.0;            // Hz; < 0: the model's choice, 0: no frequency continuation
  bool force = false;            // run even when the size estimate says it does not fit
  bool data_type_given = false;  // filled after parsing
};

CLI::App* add_calibrate_command(CLI::App& app, CalibrateOptions& options);
int run_calibrate(CalibrateOptions options);

}  // namespace rollnoise
