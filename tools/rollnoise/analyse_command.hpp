#pragma once
// `rollnoise analyse FILE.wav|FILE.uff [--full-scale PA] [--out DIR]`: spectra and levels of a
// recording, written like `simulate` writes them, so measurement and simulation compare directly.
#include <string>

namespace CLI {
class App;
}

namespace rollnoise {

struct AnalyseOptions {
  std::string file;
  double full_scale = 0.0;  // Pa of sample value 1.0 in a WAV; 0: from the WAV's comment
  std::string out;
};

CLI::App* add_analyse_command(CLI::App& app, AnalyseOptions& options);
int run_analyse(const AnalyseOptions& options);

}  // namespace rollnoise
