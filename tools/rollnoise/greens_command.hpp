#pragma once
// `rollnoise greens MODEL.toml`: a tyre model's Green's functions and mobilities, tabulated and
// drawn (ARCHITECTURE.md), so a user sees what the contact solver will convolve with and can
// compare the model's mobility with a measured one before calibrating.
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rollnoise {

struct GreensOptions {
  std::string model;                // a model file (models/tyres/NAME.toml)
  std::string out;                  // default out/<model name>_greens
  std::string frequencies;          // "F1:F2:N", evenly spaced, inclusive (Hz); default: the model's
  std::vector<double> distances;    // m along the circumference from the excitation; default: the model's
  bool force = false;               // run even when the size estimate says it does not fit
  std::string cache;                // --cache DIR (empty: the default folder, core/cache_folder.hpp)
  bool no_cache = false;
  std::string cache_limit;  // --cache-limit SIZE (empty: the case's, else the default)
};

CLI::App* add_greens_command(CLI::App& app, GreensOptions& options);
int run_greens(const GreensOptions& options);

}  // namespace rollnoise
