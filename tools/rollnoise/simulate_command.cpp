#include "simulate_command.hpp"

#include <cstdio>

#include <CLI/CLI.hpp>

#include "cache_command.hpp"
#include "core/cache_folder.hpp"
#include "core/case_file.hpp"
#include "simulation/case_run.hpp"

namespace rollnoise {

CLI::App* add_simulate_command(CLI::App& app, SimulateOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Roll a tyre model over a road: contact forces and displacements at every time step.\n"
      "Writes contact.csv, summary.json and plots (PNG with their gnuplot scripts). Tyre cases\n"
      "(model plate, two_layer or tabulated) also write contact.h5 and the sound at the CPX and SPB\n"
      "microphones: spectrum.csv, levels in summary.json, sound_power.csv and <receiver>.wav (with\n"
      "spb_passby.wav). A two_layer tyre's modes are tabulated and fitted once and then cached, and\n"
      "so is the radiation's equivalent-source solve per anchor frequency (see `rollnoise cache`).");
  cmd->add_option("case", options.case_file, "Case file (TOML) with [tyre], [road], [rolling], [radiation], [output]")
      ->required();
  cmd->add_option("--out", options.out,
                  "Output folder (default: [output] directory, else out/<case name>); written "
                  "atomically, an earlier rollnoise output there is replaced");
  cmd->add_option("--set", options.overrides,
                  "Override a case value: section.key=value (value as TOML; bare words are strings). Repeatable")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);  // one value per --set, so a case file after it stays the case
  add_cache_options(*cmd, options.cache, options.no_cache, options.cache_limit);
  cmd->add_flag("--force", options.force,
                "Run even when the estimate of the run's memory or output exceeds what the machine has");
  cmd->footer(
      "Example:\n  rollnoise simulate models/cases/larsson2000_sdof_sine.toml --out out/sdof "
      "--set rolling.static_load=3");
  return cmd;
}

int run_simulate(const SimulateOptions& options) {
  const CaseFile file = CaseFile::load(options.case_file, options.overrides);
  CaseRunOptions run;
  run.force = options.force;
  run.cache = usable_cache_folder(options.cache, options.no_cache);
  run.cache_limit = parse_cache_limit(options.cache_limit);
  const CaseResult result = run_case(file, options.out, run);
  std::printf("rollnoise: wrote %s (%s)\n", result.out.string().c_str(), result.written.c_str());
  return 0;
}

}  // namespace rollnoise
