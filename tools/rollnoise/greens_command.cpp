#include "greens_command.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cache_command.hpp"
#include "core/cache_folder.hpp"
#include "core/error.hpp"
#include "simulation/greens_run.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

namespace {

// "F1:F2:N": N frequencies evenly spaced from F1 to F2 inclusive, Hz.
std::vector<double> parse_frequencies(const std::string& text) {
  const auto bad = [&](const std::string& why) -> InputError {
    return InputError("command line", "--frequencies", "'" + text + "': " + why);
  };
  const auto first = text.find(':');
  const auto second = first == std::string::npos ? std::string::npos : text.find(':', first + 1);
  if (second == std::string::npos || text.find(':', second + 1) != std::string::npos)
    throw bad("expected F1:F2:N (Hz, Hz, a count), such as 0:5000:501");
  double f1 = 0.0, f2 = 0.0;
  long long n = 0;
  try {
    std::size_t used = 0;
    const std::string a = text.substr(0, first), b = text.substr(first + 1, second - first - 1),
                      c = text.substr(second + 1);
    f1 = std::stod(a, &used);
    if (used != a.size()) throw std::invalid_argument(a);
    f2 = std::stod(b, &used);
    if (used != b.size()) throw std::invalid_argument(b);
    n = std::stoll(c, &used);
    if (used != c.size()) throw std::invalid_argument(c);
  } catch (const std::logic_error&) {
    throw bad("F1 and F2 must be numbers and N an integer");
  }
  if (!std::isfinite(f1) || !std::isfinite(f2) || f1 < 0.0) throw bad("F1 and F2 must be finite and F1 >= 0");
  if (n < 1 || n > kMaxGreensFrequencies) throw bad("N must be from 1 to " + std::to_string(kMaxGreensFrequencies));
  if (n == 1 ? f2 != f1 : !(f2 > f1)) throw bad("F2 must be above F1 (or equal to it with N = 1)");
  return evenly_spaced(f1, f2, n);
}

}  // namespace

CLI::App* add_greens_command(CLI::App& app, GreensOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "greens",
      "Tabulate and draw a tyre model's Green's functions and mobilities: receptance.csv and mobility.csv\n"
      "(frequency_hz,distance_m,re,im), greens.h5, the Green's function along the circumference (cf. the\n"
      "paper's Fig. 5a) and the point and transfer mobility, each plot with its gnuplot script. For a\n"
      "two_layer model also modal_receptance.h5, its modal table (docs/greens/tabulated_layout.md) at the\n"
      "pole fit's frequencies, which a model file with model = \"tabulated\" can name.");
  cmd->add_option("model", options.model,
                  "A model file (models/tyres/NAME.toml): sdof, coupled_sdof, plate, two_layer or tabulated")
      ->required();
  cmd->add_option("--out", options.out, "Output folder (default out/<model name>_greens); written atomically");
  add_cache_options(*cmd, options.cache, options.no_cache, options.cache_limit);
  cmd->add_option("--frequencies", options.frequencies,
                  "F1:F2:N, N frequencies evenly spaced from F1 to F2 inclusive, Hz (default 0 to the model's "
                  "top frequency, 501 of them: 5 kHz in 10 Hz steps for a tyre); the row at 0 Hz is the static compliance");
  cmd->add_option("--distances", options.distances,
                  "Response points, m along the circumference on the centre line from the excitation at the belt "
                  "centre, comma separated (default: 0, 0.05, 0.1, 0.2, 0.5 for a tyre; the points of a point model)")
      ->delimiter(',')
      ->allow_extra_args(false);
  cmd->add_flag("--force", options.force,
                "Run even when the estimate of the tables' memory or output (--frequencies × --distances) "
                "exceeds what the machine has");
  cmd->footer(
      "Examples:\n"
      "  rollnoise greens models/tyres/passenger_205_55R16.toml --out out/plate_greens\n"
      "  rollnoise greens models/tyres/passenger_205_55R16.toml --frequencies 0:2000:201 --distances 0,0.1\n"
      "  rollnoise greens models/tyres/passenger_205_55R16_two_layer.toml --out out/two_layer_greens\n"
      "    also writes out/two_layer_greens/modal_receptance.h5; a model file with model = \"tabulated\" and\n"
      "    file = \"PATH\" (relative to that model file's folder) reads it back.");
  return cmd;
}

int run_greens(const GreensOptions& options) {
  const fs::path input(options.model);
  GreensRunOptions run;
  run.model = options.model;
  // The same cache folder as simulate's (two-layer tables, mode fits).
  run.cache = usable_cache_folder(options.cache, options.no_cache);
  run.cache_limit = parse_cache_limit(options.cache_limit);
  run.distances = options.distances;
  run.force = options.force;
  // The option's syntax is the command line's: read here, before the model is built.
  if (!options.frequencies.empty()) run.frequencies = parse_frequencies(options.frequencies);
  const fs::path out = options.out.empty() ? fs::path("out") / (input.stem().string() + "_greens") : fs::path(options.out);
  const GreensRun greens = rollnoise::run_greens(run, out);
  write_greens_outputs(out, greens);
  std::printf("rollnoise: wrote %s (receptance.csv, mobility.csv, greens.h5, %ssummary.json and plots): %s, static "
              "point compliance %.4g m/N\n",
              out.string().c_str(), greens.modal_table ? "modal_receptance.h5, " : "", greens.response->model().c_str(),
              greens.summary["static_compliance_m_per_N"][0]["value"].get<double>());
  return 0;
}

}  // namespace rollnoise
