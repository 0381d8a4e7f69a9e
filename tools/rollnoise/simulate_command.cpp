#include "simulate_command.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "contact/point_contact.hpp"
#include "contact/rolling_settings.hpp"
#include "core/case_file.hpp"
#include "core/error.hpp"
#include "core/output_directory.hpp"
#include "core/progress.hpp"
#include "greens/greens_model.hpp"
#include "greens/model_factory.hpp"
#include "point_contact_output.hpp"
#include "road/road_profile.hpp"
#include "run_size.hpp"
#include "tyre_simulation.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

CLI::App* add_simulate_command(CLI::App& app, SimulateOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Roll a tyre model over a road: contact forces and displacements at every time step.\n"
      "Writes contact.csv, summary.json and plots (PNG with their gnuplot scripts). Tyre cases\n"
      "(model plate, two_layer or tabulated) also write contact.h5 and the sound at the CPX and SPB\n"
      "microphones: spectrum.csv, levels in summary.json, sound_power.csv and <receiver>.wav (with\n"
      "spb_passby.wav). A two_layer tyre's modes are tabulated and fitted once and then cached\n"
      "($ROLLNOISE_CACHE, else $XDG_CACHE_HOME/rollnoise or ~/.cache/rollnoise).");
  cmd->add_option("case", options.case_file, "Case file (TOML) with [tyre], [road], [rolling], [radiation], [output]")
      ->required();
  cmd->add_option("--out", options.out,
                  "Output folder (default: [output] directory, else out/<case name>); written "
                  "atomically, an earlier rollnoise output there is replaced");
  cmd->add_option("--set", options.overrides,
                  "Override a case value: section.key=value (value as TOML; bare words are strings). Repeatable")
      ->type_name("KEY=VALUE");
  cmd->add_flag("--force", options.force,
                "Run even when the estimate of the run's memory or output exceeds what the machine has");
  cmd->footer(
      "Example:\n  rollnoise simulate models/cases/larsson2000_sdof_sine.toml --out out/sdof "
      "--set rolling.static_load=3");
  return cmd;
}

int run_simulate(const SimulateOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const CaseFile file = CaseFile::load(options.case_file, options.overrides);
  file.reject_unknown_sections({"tyre", "road", "rolling", "radiation", "output"});
  try {
    fs::path out = options.out;
    if (out.empty()) {
      const std::string directory = file.optional_section("output").text("directory", "");
      out = !directory.empty() ? fs::path(directory) : fs::path("out") / fs::path(file.path()).stem();
    }
    const std::string kind = file.section("tyre").choice("model", {"sdof", "coupled_sdof", "plate", "two_layer", "tabulated"});
    if (kind != "sdof" && kind != "coupled_sdof") {
      return run_tyre_simulation(file, out, started, options.force);
    }
    const ConfigTable tyre = file.section("tyre");
    if (file.top().contains("radiation")) {
      throw InputError(file.name(), "radiation",
                       "point models (sdof, coupled_sdof) have no radiating surface; [radiation] needs a tyre model "
                       "(\"plate\", \"two_layer\" or \"tabulated\")");
    }
    const ConfigTable road_table = file.section("road");
    const ConfigTable rolling = file.section("rolling");
    const ConfigTable output = file.optional_section("output");

    const std::unique_ptr<GreensModel> model = make_greens_model(tyre);
    const RollingSettings settings = read_rolling_settings(rolling);
    check_run_fits(estimate_point_run(settings.steps() + 1, static_cast<std::uint64_t>(model->point_count()), file.name()),
                   available_memory_bytes(), available_disk_bytes(out), options.force);
    output.text("directory", "");
    const bool plots = output.boolean("plots", true);
    output.reject_unknown_keys();

    double trail = 0.0;
    for (double offset : model->contact_point_offsets()) trail = std::max(trail, offset);
    const std::unique_ptr<RoadProfile> road =
        make_road_profile(road_table, -trail, settings.speed * settings.duration);

    StagedOutputDirectory staged(out);

    for (const auto& warning : check_time_step(*model, settings.time_step)) {
      std::fprintf(stderr, "rollnoise: warning: %s: %s\n", rolling.source_of("time_step").c_str(),
                   warning.c_str());
    }
    ProgressReporter progress("simulate " + fs::path(file.path()).filename().string(), settings.steps() + 1);
    const ContactTrace trace = simulate_point_contact(*model, *road, settings, &progress);

    write_contact_csv(staged.staging() / "contact.csv", trace);
    if (plots) {
      plot_contact(staged.staging(), trace, model->name() + " on a " + road->type() + " road");
    }
    nlohmann::json summary = summarise_contact(trace);
    summary["case"] = file.name();
    summary["model"] = model->name();
    summary["road"] = road->type();
    summary["settings"] = {{"speed_m_per_s", settings.speed},
                           {"duration_s", settings.duration},
                           {"time_step_s", settings.time_step},
                           {"steps", settings.steps()},
                           {"static_load_N", settings.static_load},
                           {"history", to_string(settings.history)},
                           {"discretisation", to_string(settings.discretisation)}};
    summary["warnings"] = trace.warnings;
    summary["rollnoise_version"] = ROLLNOISE_VERSION;
    summary["wall_time_s"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    write_text_file(staged.staging() / "summary.json", summary.dump(2) + "\n");
    staged.commit();
    std::printf("rollnoise: wrote %s (contact.csv, summary.json%s)\n", out.string().c_str(),
                plots ? ", contact.png" : "");
    return 0;
  } catch (const InputError& error) {
    throw error.with_source(file.name());
  }
}

}  // namespace rollnoise
