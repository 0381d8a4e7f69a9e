#include "analyse_command.hpp"

#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "simulation/recording_analysis.hpp"
#include "number_checks.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

CLI::App* add_analyse_command(CLI::App& app, AnalyseOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "analyse",
      "Spectra and levels of a recording: third-octave band levels (IEC 61260-1 filters), A-weighting\n"
      "(IEC 61672-1), Leq, LAeq and LAFmax. Writes spectrum.csv, summary.json and spectrum.png.");
  cmd->add_option("file", options.file, "A WAV file (each channel a receiver ch1, ch2, ...) or a UFF file with "
                                        "dataset 58/58b time records of sound pressure in Pa")
      ->required();
  cmd->add_option("--full-scale", options.full_scale,
                  "Pressure in Pa of a WAV sample value of 1.0 (default: from the WAV's comment, as rollnoise writes it)")
      ->check(positive_number());
  cmd->add_option("--out", options.out, "Output folder (default out/<file name>); written atomically");
  cmd->footer("Example:\n  rollnoise analyse recording.wav --full-scale 20 --out out/recording");
  return cmd;
}

int run_analyse(const AnalyseOptions& options) {
  const RecordingAnalysis analysis = analyse_recording(options.file, options.full_scale);
  const fs::path out = options.out.empty() ? fs::path("out") / fs::path(options.file).stem() : fs::path(options.out);
  write_recording_analysis(out, analysis);
  std::printf("rollnoise: wrote %s (spectrum.csv, summary.json, spectrum.png)\n", out.string().c_str());
  return 0;
}

}  // namespace rollnoise
