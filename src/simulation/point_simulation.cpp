#include "simulation/point_simulation.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "contact/point_contact.hpp"
#include "contact/rolling_settings.hpp"
#include "core/case_file.hpp"
#include "core/error.hpp"
#include "core/output_directory.hpp"
#include "core/progress.hpp"
#include "greens/greens_model.hpp"
#include "greens/model_factory.hpp"
#include "road/road_profile.hpp"
#include "simulation/point_contact_output.hpp"
#include "greens/discrete_kernel.hpp"
#include "simulation/run_size.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

CaseResult run_point_simulation(const CaseFile& file, const fs::path& out, std::chrono::steady_clock::time_point started,
                                const CaseRunOptions& options) {
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
  // The kernel is cut where it has decayed (discrete_kernel.hpp), at most the run's length.
  check_run_fits(estimate_point_run(settings.steps() + 1, static_cast<std::uint64_t>(model->point_count()),
                                    decay_length(*model, settings.time_step), file.name()),
                 available_memory_bytes(), available_disk_bytes(out), options.force);
  output.text("directory", "");
  const bool plots = output.boolean("plots", true);
  output.reject_unknown_keys();

  double trail = 0.0;
  for (double offset : model->contact_point_offsets()) trail = std::max(trail, offset);
  const std::unique_ptr<RoadProfile> road = make_road_profile(road_table, -trail, settings.speed * settings.duration);

  StagedOutputDirectory staged(out);

  for (const auto& warning : check_time_step(*model, settings.time_step)) {
    std::fprintf(stderr, "rollnoise: warning: %s: %s\n", rolling.source_of("time_step").c_str(), warning.c_str());
  }
  // Always there, drawn only when asked: its updates poll Ctrl-C also in a study's quiet cases.
  ProgressReporter progress("simulate " + fs::path(file.path()).filename().string(), settings.steps() + 1, {},
                            options.progress, options.progress_sink);
  const ContactTrace trace = simulate_point_contact(*model, *road, settings, &progress);
  progress.finish();

  write_contact_csv(staged.staging() / "contact.csv", trace);
  if (plots) {
    plot_contact(staged.staging(), trace, model->name() + " on a " + road->type() + " road");
  }
  nlohmann::json summary = summarise_contact(trace);
  summary["case"] = file.name();
  summary["paths_outside_case_folder"] = file.paths_outside_folder();  // via ".." or a symlink
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
  summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  write_text_file(staged.staging() / "summary.json", summary.dump(2) + "\n");
  if (!options.case_text.empty()) write_text_file(staged.staging() / "case.toml", options.case_text);
  staged.commit();
  return {out, std::move(summary), std::string("contact.csv, summary.json") + (plots ? ", contact.png" : "")};
}

}  // namespace rollnoise
