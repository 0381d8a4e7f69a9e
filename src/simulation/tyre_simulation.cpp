#include "simulation/tyre_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "contact/rolling_settings.hpp"
#include "contact/rolling_tyre.hpp"
#include "contact/tread_pattern_reader.hpp"
#include "core/cache_limit.hpp"
#include "core/case_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/gnuplot.hpp"
#include "core/output_directory.hpp"
#include "core/progress.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/centre_line_response.hpp"
#include "greens/modal_table_cache.hpp"
#include "greens/plate_factory.hpp"
#include "greens/rolling_tyre_model.hpp"
#include "greens/tread_compliance.hpp"
#include "road/road_surface.hpp"
#include "core/hdf5_writer.hpp"
#include "radiation/belt_sampling.hpp"
#include "radiation/tyre_surface_mesh.hpp"
#include "response/surface_response.hpp"
#include "acoustics/band_power.hpp"
#include "simulation/air_pumping_outputs.hpp"
#include "simulation/energy_budget_output.hpp"
#include "simulation/greens_plots.hpp"
#include "simulation/pattern_outputs.hpp"
#include "simulation/run_size.hpp"
#include "simulation/stage_times.hpp"
#include "simulation/tyre_sound.hpp"
#include "simulation/tyre_step_outputs.hpp"
#include "simulation/tyre_run_summary.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

Eigen::MatrixXd tread_compliance(const TreadSettings& tread, const TyreGrid& grid) {
  switch (tread.type) {
    case TreadSettings::Type::winkler:
      return winkler_compliance(grid.points(), grid.dx(), grid.dy(), tread.stiffness_per_area);
    case TreadSettings::Type::halfspace:
      return halfspace_compliance(grid.positions(), grid.dx(), grid.dy(), tread.youngs_modulus, tread.poisson_ratio);
    case TreadSettings::Type::nonlinear:
      break;  // no linear local part: the springs act in the contact solve
  }
  return Eigen::MatrixXd::Zero(grid.points(), grid.points());
}

// Over a porous road ([road.absorption]) the radiation's plane is its impedance plane: the
// admittance at each anchor, as a plain function (the radiation does not link the road); empty
// over a rigid road.
PlaneAdmittance radiation_plane_admittance(const RoadAbsorption& absorption) {
  if (absorption.rigid()) return {};
  return [absorption](double frequency) { return absorption.normalised_admittance(frequency); };
}

void write_totals_csv(const fs::path& path, const TyreContactTrace& t) {
  std::ofstream out(path, std::ios::binary);
  CsvWriter csv(out, {"time", "total_force", "contact_area", "contact_length"});
  for (Eigen::Index n = 0; n < t.time.size(); ++n) {
    const double row[] = {t.time(n), t.total_force(n), t.contact_area(n), t.contact_length(n)};
    csv.row(row, 4);
  }
  close_output_file(out, path);
}

// The pressure over the window at one step (its forces): x, y, pressure (Pa), for a gnuplot image.
void write_pressure_snapshot(const fs::path& path, const Eigen::VectorXd& force, const TyreGrid& grid) {
  std::ofstream out(path, std::ios::binary);
  CsvWriter csv(out, {"x", "y", "pressure"});
  const double area = grid.dx() * grid.dy();
  for (int j = 0; j < grid.lateral; ++j) {
    for (int i = 0; i < grid.window; ++i) {
      const double row[] = {grid.x(i), grid.y(j), force(i + static_cast<Eigen::Index>(grid.window) * j) / area};
      csv.row(row, 3);
    }
    out << '\n';  // blank line between scan lines, as gnuplot's image style expects
  }
  close_output_file(out, path);
}

// The radiating body (issue 10 §2): the loaded tyre, flattened over the run's mean contact patch
// (centred under the axle) with the axle lowered by the indentation; beyond the patch the belt's
// own deflected shape along the circumference (tyre_surface_mesh.hpp). The shoulders beyond the
// patch's width are lifted by the crown's drop there, at least the clearance. The patch is
// measured over the run's first steps (all of a run of up to 4096: tyre_step_outputs.hpp), so
// that the belt can be sampled onto the mesh as the run goes on.
// Not the steady rolling patch on a smooth road, which would be the same on every road and let
// cases on other surfaces share the radiation cache's entries (issue 12): on the rough library
// surfaces it is 7-12 mm shorter than the run's own mean patch (0.1075 m against 0.1193 m on
// DAC 11, 0.1149 m on SMA 11 at 80 km/h), which puts the horn's throat inside the tread the run
// holds against the texture and moved the levels by 1.0-1.9 dB (docs/radiation_cache.md). The
// mean patch is where this run's tread leaves the road.
void deform_radiating_body(TyreSoundSettings& sound, const RadiatingPatch& patch, const TyreGrid& grid,
                           const RollingTyreModel& model, const CaseFile& file) {
  if (sound.radiation.mesh.geometry != TyreGeometry::deformed) return;
  TyreDeformation& shape = sound.radiation.mesh.deformation;
  shape.patch_length = patch.length;
  shape.patch_width = std::min(patch.width, grid.width);
  shape.indentation = patch.indentation;
  shape.belt_tension = model.belt_tension;
  shape.belt_bending = model.belt_bending;
  shape.foundation_stiffness = model.foundation_stiffness;
  const double crown_drop =
      model.crown_radius > 0.0
          ? (0.25 * grid.width * grid.width - 0.25 * shape.patch_width * shape.patch_width) / (2.0 * model.crown_radius)
          : 0.0;
  shape.shoulder_lift = std::max(crown_drop, sound.radiation.mesh.clearance);
  if (!(shape.patch_length > 0.0 && shape.indentation > 0.0)) {
    std::fprintf(stderr, "rollnoise: warning: no contact patch: the tyre radiates undeformed\n");
    sound.radiation.mesh.geometry = TyreGeometry::undeformed;
  } else if (const std::string inside = receivers_outside_tyre(sound); !inside.empty()) {
    const ConfigTable radiation_table = file.optional_section("radiation");
    throw InputError(radiation_table.source_of("receivers"), "[radiation] receivers", inside);
  }
}

// The paper's Fig. 5b: the radial displacement of one material point over one revolution.
void write_revolution(const fs::path& dir, const std::vector<double>& revolution, double dt, PlotBatch& plots) {
  std::ofstream out(dir / "revolution.csv", std::ios::binary);
  CsvWriter csv(out, {"angle_deg", "time", "displacement"});
  const auto n = revolution.size();
  for (std::size_t k = 0; k < n; ++k) {
    const double row[] = {360.0 * static_cast<double>(k) / static_cast<double>(n), static_cast<double>(k) * dt,
                          revolution[k]};
    csv.row(row, 3);
  }
  close_output_file(out, dir / "revolution.csv");
  std::ostringstream gp;
  gp << "# Radial displacement of a belt point over one revolution (cf. Larsson 2000, Fig. 5b).\n"
     << "set terminal pngcairo size 1000,500 noenhanced font 'DejaVu Sans,10'\n"
     << "set output 'revolution.png'\nset datafile separator ','\nset grid\n"
     << "set title 'Radial displacement of one belt point (mid-width) over one revolution; contact at 180 deg'\n"
     << "set xlabel 'angle turned from the top (deg)'\nset ylabel 'displacement (mm)'\nset xrange [0:360]\n"
     << "plot 'revolution.csv' skip 1 using 1:($3*1e3) with lines lw 1.5 notitle\n";
  write_plot(dir, "revolution", gp.str(), &plots);
}

void plot_tyre_run(const fs::path& dir, const std::string& title, double time_of_snapshot, PlotBatch& plots) {
  std::ostringstream force;
  force << "# Drawn by rollnoise from contact.csv; run `gnuplot total_force.gp` to redraw.\n"
        << "set terminal pngcairo size 1000,500 noenhanced font 'DejaVu Sans,10'\n"
        << "set output 'total_force.png'\nset datafile separator ','\nset grid\n"
        << "set title \"" << title << ": total contact force\"\n"
        << "set xlabel 'time (s)'\nset ylabel 'total force (N)'\nset y2label 'contact area (cm²)'\n"
        << "set ytics nomirror\nset y2tics\n"
        << "plot 'contact.csv' using 1:2 with lines lw 1.5 title 'total force', \\\n"
        << "     '' using 1:($3*1e4) axes x1y2 with lines lw 1 lc rgb '#2ca02c' title 'contact area'\n";
  write_plot(dir, "total_force", force.str(), &plots);
  std::ostringstream map;
  map << "# Drawn by rollnoise from pressure_snapshot.csv; run `gnuplot pressure_map.gp` to redraw.\n"
      << "set terminal pngcairo size 900,600 noenhanced font 'DejaVu Sans,10'\n"
      << "set output 'pressure_map.png'\nset datafile separator ','\n"
      << "set title \"" << title << ": contact pressure at t = " << time_of_snapshot
      << " s (x along the direction of travel)\"\n"
      << "set xlabel 'x (mm)'\nset ylabel 'y (mm)'\nset cblabel 'pressure (kPa)'\nset size ratio -1\n"
      << "set palette defined (0 'white', 1 '#fde725', 2 '#21918c', 3 '#440154')\n"
      << "plot 'pressure_snapshot.csv' skip 1 using ($1*1e3):($2*1e3):($3*1e-3) with image notitle\n";
  write_plot(dir, "pressure_map", map.str(), &plots);
}

// Cells around the tyre: as given, or (by default) the least even FFT-friendly count that lets one
// step per cell carry the band_top band (rolling_settings.hpp), and never fewer than the model's orders
// need (2·M) nor than the paper's 512.
int circumferential_points(const TyreRollingSettings& settings, const RollingTyreModel& model,
                           const ConfigTable& rolling) {
  if (settings.points_circumferential > 0) return settings.points_circumferential;
  if (settings.band_top <= 0.0) return 512;
  const int needed = circumferential_points_for_band(settings.band_top, 2.0 * std::numbers::pi * model.radius,
                                                     settings.speed);
  constexpr int largest = 1 << 16;
  if (needed > largest)
    rolling.fail("band_top", "needs " + std::to_string(needed) + " cells around the tyre at this speed (at most " +
                                 std::to_string(largest) + "): lower band_top, raise speed, or give "
                                 "points_circumferential (the band is then carried by sub-steps)");
  return std::max({needed, 512, 2 * model.modes->orders()});
}

// The contact grid of a run: the cells around (circumferential_points) and across, the window.
TyreGrid tyre_grid(const TyreRollingSettings& settings, const RollingTyreModel& model, const ConfigTable& rolling) {
  TyreGrid grid;
  grid.radius = model.radius;
  grid.width = model.width;
  grid.circumferential = circumferential_points(settings, model, rolling);
  grid.lateral = settings.points_lateral;
  grid.crown_radius = model.crown_radius;
  grid.tread_width = model.tread_width;
  grid.window = std::max(2, static_cast<int>(std::lround(settings.contact_window / grid.dx())));
  try {
    grid.validate();
  } catch (const std::invalid_argument& error) {
    throw InputError(rolling.source_of("contact_window"), "[rolling]", error.what());
  }
  return grid;
}

// What the run will hold and write, for its estimate (run_size.hpp): every engine and output.
TyreRunSize tyre_run_size(const TyreGrid& grid, const RollingModes& rolling_modes, const TyreRollingSettings& settings,
                          const TyreSoundSettings& sound, ContactFields fields, std::size_t steps, double dt,
                          bool stream_sound) {
  TyreRunSize size;
  size.samples = steps + 1;
  size.window_points = static_cast<std::uint64_t>(grid.points());
  size.window_columns = static_cast<std::uint64_t>(grid.window);
  size.lateral = static_cast<std::uint64_t>(grid.lateral);
  size.circumferential = static_cast<std::uint64_t>(grid.circumferential);
  size.direct_history = settings.history == HistoryKind::direct;
  for (Eigen::Index r = 0; r < static_cast<Eigen::Index>(rolling_modes.lateral_modes()) * (rolling_modes.orders() + 1); ++r)
    size.modal_poles += rolling_modes.mode(r).size();
  size.radiating = sound.enabled;
  if (sound.enabled) {
    TyreRadiationSettings radiation = sound.radiation;
    radiation.sample_rate_hz = 1.0 / dt;
    size.radiation_solve_bytes = radiation_solve_bytes(radiation, radiation_thread_limit(radiation));
  }
  size.radiation_block = stream_sound ? TyreRadiationStream::block_samples(1.0 / dt) : 0;
  size.receivers = sound.enabled && sound.wav ? sound.receivers.size() : 0;
  size.audio_frames = static_cast<std::uint64_t>(std::max(settings.duration, sound.wav_duration) * sound.audio_rate);
  size.absorbing_pass_by = size.receivers > 0 && static_cast<bool>(sound.radiation.admittance);
  size.fields = fields;
  return size;
}

}  // namespace

CaseResult run_tyre_simulation(const CaseFile& file, const fs::path& out, std::chrono::steady_clock::time_point started,
                               const CaseRunOptions& options) {
  const ConfigTable tyre = file.section("tyre");
  const ConfigTable road_table = file.section("road");
  const ConfigTable rolling = file.section("rolling");
  const ConfigTable output = file.optional_section("output");
  // Where the run's time goes (summary.json "stage_times_s"), from here: the case's parsing before
  // is in the wall time only.
  StageTimes stages;

  // Every table is read and checked before the tyre's model is made (the two-layer tyre's table
  // and fits take tens of seconds without the cache): a wrong key costs no wait. The road is made
  // after the model, since it needs the grid, but its keys are checked here.
  RollingTyreSpec tyre_spec = read_rolling_tyre_spec(tyre);
  const TyreRollingSettings settings = read_tyre_rolling_settings(rolling);
  std::shared_ptr<const TreadPattern> pattern;
  if (std::optional<TreadPattern> read = read_tread_pattern(tyre, tyre_spec.radius, tyre_spec.tread_width)) {
    if (settings.contact_law == ContactLaw::texture)
      throw InputError(tyre.source_of("pattern"), "[tyre.pattern]",
                       "is not available with [rolling] contact_law = \"texture\": each cell's texture law presses "
                       "the whole cell's rubber onto the road, where a cell over a groove has only its block's share; "
                       "use contact_law = \"rigid\" (the default) with a pattern");
    pattern = std::make_shared<const TreadPattern>(std::move(*read));
  }
  const bool plots = output.boolean("plots", true);
  // What contact.h5 holds (tyre_step_outputs.hpp).
  const ContactFields fields = *contact_fields_from(output.choice("fields", {"contact", "all", "none"}, "contact"));
  output.text("directory", "");
  // The radiated band reaches the upper edge of the band_top band (5623 Hz for 5 kHz) unless
  // max_frequency says otherwise; with band_top = 0 the old default, 3 kHz.
  TyreSoundSettings sound =
      read_tyre_sound_settings(file.optional_section("radiation"), output, tyre_spec.radius, tyre_spec.width,
                               settings.band_top > 0.0 ? band_top_edge(settings.band_top) : 3000.0);
  output.reject_unknown_keys();
  (void)make_road_surface(road_table, 0.0, 0.0, 0.0, RoadBuild::keys_only);
  const RollingTyreModel model = make_rolling_tyre_model(std::move(tyre_spec), options.cache);
  if (sound.radiation.threads == 0) sound.radiation.threads = options.radiation_threads;
  if (options.cache_limit) sound.cache_limit = *options.cache_limit;
  // A folder over its limit (a smaller limit than before, entries of the other caches, an older
  // version's larger entries) is trimmed before the run adds to it.
  if (options.cache) keep_cache_within(*options.cache, sound.cache_limit);

  const TyreGrid grid = tyre_grid(settings, model, rolling);
  // Sub-steps per cell so that the contact steps carry the band_top band (rolling_settings.hpp).
  const int substeps = substeps_for_band(settings.band_top, grid.dx(), settings.speed);
  const double dt = grid.dx() / (substeps * settings.speed);
  std::unique_ptr<RollingModes> rolling_modes;
  try {
    rolling_modes = std::make_unique<RollingModes>(*model.modes, grid, dt, substeps);
  } catch (const std::invalid_argument& error) {
    throw InputError(tyre.source_of("circumferential_modes"), "[tyre] circumferential_modes", error.what());
  }
  // The local compliance: the plate's separate tread, or, for a model that includes its tread,
  // the static compliance of its modes beyond the table (static_residual.hpp).
  std::vector<double> lateral_y(static_cast<std::size_t>(grid.lateral));
  for (int j = 0; j < grid.lateral; ++j) lateral_y[static_cast<std::size_t>(j)] = grid.y(j);
  const Eigen::MatrixXd local = model.tread      ? tread_compliance(*model.tread, grid)
                                : model.residual ? model.residual(grid.window, grid.dx(), lateral_y, grid.dy())
                                                 : Eigen::MatrixXd::Zero(grid.points(), grid.points());
  // The run samples t = n·dt for n = 0 … steps (rolling_tyre.cpp), which can end up to half a
  // step after `duration`: the road must reach the last step's position.
  if (!(settings.duration / dt < 1e15)) rolling.fail("duration", "gives more than 1e15 time steps; shorten it");
  const auto steps = static_cast<std::size_t>(std::llround(settings.duration / dt));
  // A run longer than a block streams the tread velocity through the radiation (issue 13).
  const bool stream_sound = sound.enabled && TyreSoundStream::wanted(steps + 1, 1.0 / dt);
  check_run_fits(estimate_tyre_run(tyre_run_size(grid, *rolling_modes, settings, sound, fields, steps, dt, stream_sound), file.name()),
                 available_memory_bytes(), available_disk_bytes(out), options.force);
  stages.lap("model_and_grid");
  const double travel = settings.speed * dt * static_cast<double>(steps);
  // Road y is measured from the wheel's centre line.
  const std::unique_ptr<RoadSurface> road =
      make_road_surface(road_table, grid.x(0) - 3.0 * grid.dx(), grid.x(grid.window - 1) + 3.0 * grid.dx() + travel,
                        0.5 * grid.contact_width());
  stages.lap("road");
  // What the road says a tyre should know (a single measured line under the whole patch, a
  // record too short for a tyre's wavelengths): on stderr now and in the summary.
  std::vector<std::string> road_warnings;
  if (grid.lateral > 1) road_warnings = road->warnings();
  for (const auto& warning : road_warnings) std::fprintf(stderr, "rollnoise: warning: %s\n", warning.c_str());

  StagedOutputDirectory staged(out);
  std::optional<ProgressReporter> progress;
  if (options.progress || options.progress_sink)
    progress.emplace("simulate " + fs::path(file.path()).filename().string(), steps + 1, CancellationToken{},
                     options.progress, options.progress_sink);
  TyreRunSettings run{settings.speed, settings.duration, settings.static_load, settings.history,
                      settings.road_sampling};
  run.contact_law = settings.contact_law;
  run.pattern = pattern;
  // The air pumping is heard only through the radiation.
  run.air_pumping = sound.enabled && sound.air_pumping;
  if (run.contact_law == ContactLaw::texture) {
    if (!(model.tread_youngs_modulus > 0.0))
      throw InputError(tyre.source_of(model.model == "plate" ? "tread" : "tread_youngs_modulus"),
                       model.model == "plate" ? "[tyre.tread] youngs_modulus" : "[tyre] tread_youngs_modulus",
                       "is needed by [rolling] contact_law = \"texture\": the tread rubber's modulus at the contact's "
                       "time scale (Pa), with poisson_ratio");
    run.rubber = TreadRubber{model.tread_youngs_modulus, model.tread_poisson_ratio};
    // A road too coarse for the cells is refused now, naming the road's file, not after the setup.
    (void)cell_pixels(grid.dx(), grid.dy(), road->sample_spacing(), road_table.source_of("sample_spacing"),
                      "[road] sample_spacing");
    run.law_threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    run.law_cache = options.cache;
  }
  run.keep_fields = false;  // streamed through the step outputs below
  std::unique_ptr<NonlinearTread> springs;
  if (model.tread && model.tread->type == TreadSettings::Type::nonlinear) {
    // spring_stiffness is per area: each point carries its cell's share.
    springs = std::make_unique<NonlinearTread>(NonlinearTread{
        Eigen::VectorXd::Constant(grid.points(), model.tread->spring_stiffness * grid.dx() * grid.dy()),
        model.tread->spring_exponent});
  }
  // What each step leaves behind, taken as the contact loop runs (tyre_step_outputs.hpp).
  const auto samples = steps + 1;
  // The energy budget (issue 10 §1) of a run with radiation: the belt's velocity spectra, over
  // the whole belt and near the contact, gathered while the response stage runs.
  std::unique_ptr<PointAveragedPsd> belt_psd;
  if (sound.enabled && samples >= 8) {
    belt_psd = std::make_unique<PointAveragedPsd>(
        static_cast<std::size_t>(grid.circumferential) * static_cast<std::size_t>(grid.lateral), 1.0 / dt,
        welch_segment_for(samples, budget_max_segment),
        belt_budget_weights(grid.circumferential, grid.lateral, grid.circumference()));
  }
  sound.radiation.sample_rate_hz = 1.0 / dt;
  sound.radiation.admittance = radiation_plane_admittance(road->absorption());
  sound.cache_folder = options.cache;
  sound.progress_sink = options.progress_sink;
  TyreStepOutputSettings step_outputs{fields, staged.staging() / "contact.h5", samples, settings.speed,
                                      settings.static_load, {}, {}, belt_psd.get(), {}, true, {}};
  // A long run's radiation takes the tread velocity as the run makes it, in blocks, instead of
  // the record after the run (tyre_sound.hpp): the memory stays flat in the run's length. With
  // the energy budget (the plate's estimates), the stream also gathers the radiating velocity's
  // PSD, over the budget's Welch segment.
  std::unique_ptr<TyreSoundStream> sound_stream;
  if (stream_sound) {
    const std::size_t budget_segment =
        belt_psd && model.plate && model.tread ? welch_segment_for(samples, budget_max_segment) : 0;
    sound_stream = std::make_unique<TyreSoundStream>(sound, samples, 1.0 / dt, budget_segment,
                                                     fs::path(file.path()).filename().string(), options.progress);
    step_outputs.tread_sink = [&stream = *sound_stream](std::span<const double> v) { stream.push(v); };
  }
  if (sound.enabled) {
    // The belt onto the radiation's input mesh (the finest of its bands' meshes,
    // tyre_radiation.hpp), the tyre deformed as it rolls (deform_radiating_body).
    step_outputs.tread_sampling = [&](const RadiatingPatch& patch) {
      deform_radiating_body(sound, patch, grid, model, file);
      return belt_to_tread_matrix(grid.circumferential, grid.lateral,
                                  make_tyre_surface_mesh(radiation_mesh_levels(sound.radiation).back().spec));
    };
  }
  TyreStepOutputs outputs(*rolling_modes, std::move(step_outputs));
  stages.lap("run_setup");
  const auto contact_started = std::chrono::steady_clock::now();
  const TyreContactTrace trace =
      simulate_rolling_tyre(*rolling_modes, local, *road, run, progress ? &*progress : nullptr, springs.get(), &outputs);
  const double contact_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - contact_started).count() - trace.sink_seconds;
  stages.lap("contact_and_response");  // split below into contact_time_s and response_and_outputs_time_s
  outputs.finish();
  stages.lap("contact_h5_finish");
  for (const auto& warning : trace.warnings) std::fprintf(stderr, "rollnoise: warning: %s\n", warning.c_str());

  write_totals_csv(staged.staging() / "contact.csv", trace);
  if (run.air_pumping) write_air_pumping_csv(staged.staging() / "air_pumping.csv", trace.time, trace.air_pumping);
  // The snapshot at the largest total force: the most telling instant on a rough road.
  write_pressure_snapshot(staged.staging() / "pressure_snapshot.csv", outputs.snapshot_force(), grid);
  const std::vector<double> revolution = outputs.revolution();
  // The case's plots, drawn together before the folder is committed (core/gnuplot.hpp).
  PlotBatch plot_batch(staged.staging());
  if (plots) {
    plot_tyre_run(staged.staging(), model.model + " on a " + road->type() + " road", outputs.snapshot_time(), plot_batch);
    write_greens_circumference(staged.staging(), *make_centre_line_response(tyre, options.cache), grid.circumferential,
                               &plot_batch);
    if (!revolution.empty()) write_revolution(staged.staging(), revolution, dt * substeps, plot_batch);
  }
  if (pattern)
    write_tread_pattern_map(staged.staging(), *pattern, grid.contact_width(), model.model + " tyre",
                            plots ? &plot_batch : nullptr);

  stages.lap("contact_outputs");
  TyreRunFacts facts{file, model, grid, settings, road->type(), pattern.get(), fields, dt, substeps, steps};
  nlohmann::json summary = tyre_contact_summary(facts, trace);
  bool budget_written = false;
  if (sound.enabled) {
    std::unique_ptr<TyreBudget> budget;
    // The budget's independent estimates are the plate's (point mobility, patch receptance).
    if (belt_psd && model.plate && model.tread) {
      const KroppPlate plate(*model.plate);
      // k_c of the single-point estimate: the tread springs over the mean contact area, in
      // parallel (a nonlinear tread's springs taken as linear; a half-space tread as rigid).
      const double area = trace.contact_area.mean();
      const double contact_stiffness =
          model.tread->type == TreadSettings::Type::winkler     ? model.tread->stiffness_per_area * area
          : model.tread->type == TreadSettings::Type::nonlinear ? model.tread->spring_stiffness * area
                                                               : std::numeric_limits<double>::infinity();
      budget = std::make_unique<TyreBudget>(tyre_budget(trace, outputs.texture(), plate, *belt_psd, settings.speed, 1.0 / dt,
                                                        budget_bands(1.0 / dt, sound.radiation.max_frequency_hz),
                                                        contact_stiffness));
    }
    budget_written = budget != nullptr;
    stages.lap("energy_budget");
    const std::string source = fs::path(file.path()).filename().string();
    PlotBatch* sound_plots = plots ? &plot_batch : nullptr;
    std::optional<MonopoleSources> air;
    if (run.air_pumping) air = air_pumping_sources(trace.air_pumping);
    const MonopoleSources* air_sources = air ? &*air : nullptr;
    const nlohmann::json heard =
        sound_stream ? write_tyre_sound(staged.staging(), sound, *sound_stream, settings.speed, source, sound_plots, budget.get(),
                                        air_sources)
                     : write_tyre_sound(staged.staging(), sound, outputs.tread_velocity(), 1.0 / dt, settings.speed, source,
                                        sound_plots, budget.get(), options.progress, air_sources);
    stages.skip();
    for (const auto& [key, value] : heard.items())
      if (key != "sound_stage_times_s") summary[key] = value;
    if (run.air_pumping) add_air_pumping_contact_summary(trace.air_pumping, summary["air_pumping"]);
    const nlohmann::json& sound_stages = heard.at("sound_stage_times_s");
    for (const auto& [key, value] : sound_stages.items()) summary["stage_times_s"][key] = value;
  }
  plot_batch.draw();
  stages.lap("plots");
  std::vector<std::string> warnings = road_warnings;
  warnings.insert(warnings.end(), trace.warnings.begin(), trace.warnings.end());
  summary["warnings"] = warnings;
  summary["rollnoise_version"] = ROLLNOISE_VERSION;
  summary["contact_time_s"] = contact_seconds;
  summary["step_loop_time_s"] = trace.step_loop_seconds;
  summary["history_engine_time_s"] = trace.history_seconds;
  summary["lcp_time_s"] = trace.lcp_seconds;
  // The response stage and the streamed outputs, run step by step beside the contact loop.
  summary["response_and_outputs_time_s"] = trace.sink_seconds;
  if (trace.lcp_factorisations >= 0) summary["lcp_factorisations"] = trace.lcp_factorisations;
  summary["lcp_cg_iterations"] = trace.lcp_cg_iterations;
  const nlohmann::json run_stages = stages.json();
  for (const auto& [key, value] : run_stages.items()) summary["stage_times_s"][key] = value;
  summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  write_text_file(staged.staging() / "summary.json", summary.dump(2) + "\n");
  if (!options.case_text.empty()) write_text_file(staged.staging() / "case.toml", options.case_text);
  staged.commit();
  std::string written = fields == ContactFields::none ? "contact.csv, summary.json" : "contact.csv, contact.h5, summary.json";
  if (sound.enabled) written += ", spectrum.csv, sound_power.csv";
  if (run.air_pumping) written += ", air_pumping.csv";
  if (budget_written) written += ", budget.csv";  // the plate's estimates only
  if (sound.enabled && sound.wav) written += ", WAV files";
  if (plots) written += " and plots";
  return {out, std::move(summary), std::move(written)};
}

}  // namespace rollnoise
