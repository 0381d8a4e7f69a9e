#include "calibrate_command.hpp"

#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "calibrate/calibration.hpp"
#include "simulation/calibration_run.hpp"
#include "number_checks.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

CLI::App* add_calibrate_command(CLI::App& app, CalibrateOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "calibrate",
      "Fit a tyre model's parameters to measured point and transfer mobilities (CSV or UFF 58/58b), with Ceres:\n"
      "log-space parameters within bounds, complex-log residuals weighted per third-octave band, a Cauchy loss,\n"
      "several seeded starts, standard errors and correlations. Writes calibrated.toml (a model file that\n"
      "`simulate` takes), fit.csv, report.json and fit.png.");
  cmd->add_option("model", options.model, "Model file (TOML): the keys of a [tyre] table (models/tyres/*.toml)")
      ->required();
  cmd->add_option("--data", options.data,
                  "Measured FRFs: CSV (frequency_hz,re,im or frequency_hz,magnitude,phase_deg) or UFF dataset 58/58b "
                  "files (function type 4); several files, and several FRFs per UFF file, fit together")
      ->required()
      ->expected(1, -1);
  cmd->add_option("--fit", options.fit,
                  "Parameters to fit, by model-file key (mass, damping, stiffness, contact_stiffness, coupling; "
                  "tension_x, tension_y, bending_x, bending_y, bending_xy, foundation_stiffness, loss_factor, "
                  "mass_per_area; two_layer: belt_youngs_modulus_x/y/z, belt_shear_modulus_xy/xz/yz, belt_density, "
                  "belt_loss_factor, tread_youngs_modulus, tread_density, tread_loss_factor, tension_x, tension_y, "
                  "foundation_stiffness, foundation_loss_factor; transducer_mass). Default: sdof all, plate "
                  "tension_x, bending_x, foundation_stiffness, loss_factor; two_layer belt_youngs_modulus_x/y, "
                  "tension_x/y, foundation_stiffness, tread_youngs_modulus and the three loss factors")
      ->delimiter(',')
      ->allow_extra_args(false);
  cmd->add_option("--out", options.out,
                  "Output folder (default out/<model name>_calibrated); written atomically, an earlier rollnoise "
                  "output there is replaced");
  cmd->add_option("--data-type", options.data_type,
                  "What the data is when a file does not say: mobility (m/(N s)), receptance (m/N) or accelerance "
                  "(m/(N s^2)); default mobility; given explicitly, a file that says otherwise is an error")
      ->check(CLI::IsMember({"mobility", "receptance", "accelerance"}));
  cmd->add_option("--response", options.response,
                  "Response position X,Y in m (tyre models: x along the circumference, y across the belt from one "
                  "edge); once for every FRF without a position of its own, or once per data file")
      ->allow_extra_args(false);
  cmd->add_option("--excitation", options.excitation, "Excitation (force) position X,Y in m; as --response")
      ->allow_extra_args(false);
  cmd->add_option("--node", options.nodes, "Position of a UFF node: N=X,Y in m (repeat for each node)")
      ->allow_extra_args(false);
  cmd->add_option("--transducer-mass", options.transducer_mass,
                  "Mass (kg) of the transducer at each response point (mass loading); the starting value when "
                  "transducer_mass is fitted (default 0)")
      ->check(non_negative_number());
  cmd->add_option("--frequency-range", options.frequency_range,
                  "LO:HI in Hz: fit only these lines (within the model's valid range; two_layer solves exactly "
                  "the modes that resonate below 2 HI, HI 500 Hz by default, at most 2000 Hz)");
  cmd->add_option("--starts", options.starts,
                  "Number of starting points (the model file's values, then seeded draws within a factor of ten); "
                  "default 8, for two_layer 1")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--seed", options.seed,
                  "Seed of the starting points (default 1; the same data and seed give the same result)");
  cmd->add_option("--first-stage", options.first_stage,
                  "Frequency continuation: fit the lines up to this frequency (Hz) first, then up to twice it, and "
                  "so on to the whole band, each stage from the last one's result (default: the model's choice, "
                  "twice the lowest resonance for two_layer, none for the others; 0: the whole band at once)")
      ->check(non_negative_number());
  cmd->add_option("--loss-scale", options.loss_scale,
                  "Scale of the Cauchy loss on the log residual (default 0.25, about 2 dB or 14 degrees): lines far "
                  "beyond it (outliers) weigh less")
      ->check(positive_number());
  cmd->add_flag("--force", options.force,
                "Run even when the estimate of the fit's memory or output (its measured lines) exceeds what the "
                "machine has");
  cmd->footer(
      "Example:\n  rollnoise calibrate models/tyres/passenger_205_55R16.toml \\\n"
      "    --data data/mobility/tyre_point_mobility.csv data/mobility/tyre_transfer_mobility.csv \\\n"
      "    --fit tension_x,bending_x,foundation_stiffness,loss_factor --out out/calibrated\n"
      "Then: rollnoise simulate CASE.toml --set tyre.file=out/calibrated/calibrated.toml\n"
      "See docs/tutorials/calibrate-tyre.md; every option: docs/reference/commands.md.");
  cmd->callback([cmd, &options] { options.data_type_given = cmd->count("--data-type") > 0; });
  return cmd;
}

int run_calibrate(CalibrateOptions options) {
  CalibrationRunOptions run;
  run.model = options.model;
  run.data = options.data;
  run.fit = options.fit;
  run.data_type = options.data_type;
  run.data_type_given = options.data_type_given;
  run.response = options.response;
  run.excitation = options.excitation;
  run.nodes = options.nodes;
  run.transducer_mass = options.transducer_mass;
  run.frequency_range = options.frequency_range;
  run.starts = options.starts;
  run.seed = options.seed;
  run.loss_scale = options.loss_scale;
  run.first_stage = options.first_stage;
  run.force = options.force;
  run.note = [](const std::string& note) { std::fprintf(stderr, "rollnoise: note: %s\n", note.c_str()); };
  const fs::path out = options.out.empty() ? fs::path("out") / (fs::path(options.model).stem().string() + "_calibrated")
                                           : fs::path(options.out);
  const CalibrationRun calibration = run_calibration(run, out);
  write_calibration_outputs(out, calibration);
  const CalibrationResult& result = calibration.result;

  for (const std::string& w : result.warnings) std::fprintf(stderr, "rollnoise: warning: %s\n", w.c_str());
  std::printf("rollnoise: calibrated %s (%s) against %zu FRF%s, %zu lines: cost %.6g after %d iterations (start %d of %zu)\n",
              options.model.c_str(), result.model.c_str(), result.frfs.size(), result.frfs.size() == 1 ? "" : "s",
              result.lines, result.cost, result.iterations, result.best_start + 1, result.starts.size());
  for (const FittedParameter& p : result.fitted)
    std::printf("  %-22s %12.6g +- %-10.3g %s (file: %g)\n", p.name.c_str(), p.value, p.std_error, p.unit.c_str(),
                p.initial);
  if (result.singular_values.size() > 0) {
    std::printf("  conditioning: singular values of the weighted Jacobian (per unit of log p)");
    for (Eigen::Index i = 0; i < result.singular_values.size(); ++i) std::printf(" %.3g", result.singular_values[i]);
    std::printf("\n");
  }
  std::printf("rollnoise: wrote %s (calibrated.toml, fit.csv, report.json, fit.png)\n", out.string().c_str());
  return 0;
}

}  // namespace rollnoise
