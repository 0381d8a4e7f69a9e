#include "road_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "core/cancellation.hpp"
#include "core/case_file.hpp"
#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/gnuplot.hpp"
#include "core/output_directory.hpp"
#include "core/progress.hpp"
#include "road/mean_profile_depth.hpp"
#include "road/profile_analysis.hpp"
#include "road/profile_file.hpp"
#include "road/road_surface.hpp"
#include "road/texture_road.hpp"
#include "road/texture_spectrum.hpp"
#include "simulation/run_size.hpp"
#include "number_checks.hpp"
#include "road/profile_surface_road.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

namespace {

// A road ready for analysis: its lines on one uniform grid, and what it should look like.
struct RoadUnderTest {
  LoadedProfile profile;
  std::string description;
  std::vector<std::pair<double, double>> target;  // (wavelength m, L_tx dB) of a texture road
  nlohmann::json about;                           // a library surface's [about] table
  // Files the TOML input named outside their folder, through ".." or a symlink (referenced_file.hpp).
  std::vector<PathOutsideCaseFolder> paths_outside_folder;
};

nlohmann::json toml_to_json(const toml::table& table) {
  std::ostringstream text;
  text << toml::json_formatter{table};
  return nlohmann::json::parse(text.str());
}

// The target spectrum of type = "texture": the levels it was asked to have.
std::vector<std::pair<double, double>> texture_target(const toml::table& road) {
  std::vector<std::pair<double, double>> target;
  const toml::array* wavelengths = road["wavelengths"].as_array();
  const toml::array* levels = road["levels"].as_array();
  if (!wavelengths || !levels || wavelengths->size() != levels->size()) return target;
  for (std::size_t i = 0; i < wavelengths->size(); ++i) {
    const auto w = (*wavelengths)[i].value<double>();
    const auto l = (*levels)[i].value<double>();
    if (w && l) target.emplace_back(*w, *l);
  }
  return target;
}

// A [road] table (a case's, or a surface file's top level) built by the road factory and sampled
// on lines y_j across `width`, x = i·spacing from 0 to `length`.
RoadUnderTest generate(const RoadOptions& options) {
  const fs::path path(options.input);
  const toml::table raw = parse_toml_file(path);
  const bool is_case = raw.contains("road") && raw["road"].is_table();
  std::vector<std::string> overrides = options.overrides;
  // An aggregate road is generated as one map of its `length` (5 m by default) and, beyond,
  // in tiles as a tyre reaches them (aggregate_road.hpp). The analysis takes one map of the
  // whole length analysed, as it always has, unless the file gives its length.
  const toml::table& road_node = is_case ? *raw["road"].as_table() : raw;
  const bool given = road_node.contains("length") || std::any_of(overrides.begin(), overrides.end(), [](const std::string& o) {
                       return o.rfind("road.length=", 0) == 0 || o.rfind("length=", 0) == 0;
                     });
  if (road_node["type"].value_or(std::string()) == "aggregate" && !given && options.length > 5.0)
    overrides.push_back("road.length=" + format_number(options.length));
  std::optional<CaseFile> file;
  if (is_case) {
    file.emplace(CaseFile::load(path, overrides));
  } else {
    // A surface file: the keys of a [road] table at the top level. --set road.key=... applies.
    std::vector<std::string> top_level;
    for (const std::string& o : overrides) top_level.push_back(o.rfind("road.", 0) == 0 ? o.substr(5) : o);
    file.emplace(CaseFile::load_model(path, top_level));
  }
  const ConfigTable road = is_case ? file->section("road") : file->top();
  const toml::table& road_toml = is_case ? *file->root()["road"].as_table() : file->root();
  RoadUnderTest out;
  if (const toml::table* about = road_toml["about"].as_table()) out.about = toml_to_json(*about);
  const double half_width = options.lines > 1 ? options.width / 2.0 : 0.0;
  const std::unique_ptr<RoadSurface> surface = make_road_surface(road, 0.0, options.length, half_width);
  if (road_toml["type"].value_or(std::string()) == "texture") out.target = texture_target(road_toml);
  // A surface from measured lines shows the record's levels as its target.
  if (const auto* measured = dynamic_cast<const ProfileSurfaceRoad*>(surface.get())) {
    for (std::size_t b = 0; b < measured->record().nominal_m.size(); ++b)
      out.target.emplace_back(measured->record().nominal_m[b], measured->record().levels_db[b]);
  }
  out.description = surface->type() + " road from " + path.string();

  // A texture road is read at its own grid unless --spacing says otherwise: between its samples
  // the road is linear, which lowers the band levels near the grid's scale (by (2 + cos(2 pi h /
  // lambda)) / 3 in power on average: -1.1 dB at 5 mm on a 1 mm grid) and adds images below it
  // (issue 26: a 1 mm road read at 0.2 mm sat 0.6-1.4 dB low at 5-8 mm).
  double spacing = options.spacing;
  if (!options.spacing_given && surface->type() == "texture") {
    TextureRoadSpec spec;
    read_texture_keys(road, spec, true, 20.0);
    spacing = texture_sample_spacing(spec);
  }
  if (!options.spacing_given && surface->sample_spacing()) spacing = *surface->sample_spacing();
  const auto samples = static_cast<std::size_t>(std::floor(options.length / spacing)) + 1;
  LoadedProfile& p = out.profile;
  p.spacing_m = spacing;
  p.source = path.string();
  p.x.resize(samples);
  for (std::size_t i = 0; i < samples; ++i) p.x[i] = static_cast<double>(i) * spacing;
  ProgressReporter progress("sampling the road", static_cast<std::size_t>(options.lines) * samples);
  for (int j = 0; j < options.lines; ++j) {
    const double y = options.lines > 1 ? -half_width + options.width * j / (options.lines - 1) : 0.0;
    p.y.push_back(y);
    std::vector<double> z(samples);
    for (std::size_t i = 0; i < samples; ++i) {
      z[i] = surface->height(p.x[i], y);
      progress.update(static_cast<std::size_t>(j) * samples + i);
    }
    p.z_lines.push_back(std::move(z));
  }
  progress.finish();
  out.paths_outside_folder = file->paths_outside_folder();
  return out;
}

void write_road_csv(const fs::path& path, const LoadedProfile& p) {
  std::ofstream out(path);
  std::vector<std::string> header{"x"};
  if (p.z_lines.size() == 1) {
    header.emplace_back("z");
  } else {
    out << "# y =";
    for (std::size_t j = 0; j < p.y.size(); ++j) out << (j ? ", " : " ") << format_number(p.y[j]);
    out << "\n";
    for (std::size_t j = 0; j < p.z_lines.size(); ++j) header.push_back("z_" + std::to_string(j + 1));
  }
  CsvWriter csv(out, header);
  std::vector<double> row(header.size());
  // Seconds for a long road of many lines, with the staging folder there: polled row by row,
  // so that Ctrl-C removes it (the watchdog would leave it behind).
  const CancellationToken cancel;
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    cancel.throw_if_cancelled();
    row[0] = p.x[i];
    for (std::size_t j = 0; j < p.z_lines.size(); ++j) row[j + 1] = p.z_lines[j][i];
    csv.row(row.data(), row.size());
  }
  close_output_file(out, path);
}

void write_texture_csv(const fs::path& path, const std::vector<TextureBand>& bands) {
  std::ofstream out(path);
  CsvWriter csv(out, {"wavelength_m", "Ltx_dB"});
  for (const TextureBand& b : bands) {
    const double row[] = {b.nominal_wavelength_m, b.level_db};
    csv.row(row, 2);
  }
  close_output_file(out, path);
}

void plot_road(const fs::path& dir, const RoadUnderTest& road, bool with_target) {
  // The profile: the first metre (or all of it), in mm, as a road engineer draws it.
  std::string profile =
      "# Drawn by rollnoise road from road.csv; run `gnuplot road.gp` to redraw.\n"
      "set terminal pngcairo size 1000,400 noenhanced font 'DejaVu Sans,10'\n"
      "set output 'road.png'\nset datafile separator ','\nset grid\n"
      "set title '" + road.description + " (first metre)'\n"
      "set xlabel 'x (mm)'\nset ylabel 'z (mm)'\nset xrange [0:1000]\n"
      "plot 'road.csv' skip 1 using ($1*1000):($2*1000) with lines lw 1 title 'z" +
      std::string(road.profile.z_lines.size() > 1 ? "_1" : "") + "'\n";
  if (road.profile.z_lines.size() > 1) profile.replace(profile.find("skip 1"), 6, "skip 2");
  write_plot(dir, "road", profile);
  std::string texture =
      "# Drawn by rollnoise road from texture.csv" + std::string(with_target ? " and target.csv" : "") +
      "; run `gnuplot texture.gp` to redraw.\n"
      "set terminal pngcairo size 900,500 noenhanced font 'DejaVu Sans,10'\n"
      "set output 'texture.png'\nset datafile separator ','\nset grid\nset logscale x\n"
      "set title 'Texture level spectrum (ISO 13473-4)'\n"
      "set xlabel 'texture wavelength (mm)'\nset ylabel 'L_tx (dB re 1 um)'\n"
      "plot 'texture.csv' skip 1 using ($1*1000):2 with linespoints pt 7 title 'analysed'";
  if (with_target) texture += ", 'target.csv' skip 1 using ($1*1000):2 with linespoints pt 4 dt 2 title 'target'";
  write_plot(dir, "texture", texture + "\n");
}

}  // namespace

CLI::App* add_road_command(CLI::App& app, RoadOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "road",
      "Generate or read a road and analyse it: mean profile depth and ETD (ISO 13473-1), the third-octave\n"
      "texture spectrum (ISO 13473-4) and the unevenness class (ISO 8608). Writes road.csv, texture.csv,\n"
      "summary.json, road.png and texture.png (with their gnuplot scripts).");
  cmd->add_option("input", options.input,
                  "A TOML file with a [road] table (a case), a surface file (models/surfaces/NAME.toml), or a "
                  "profile file: CSV (x,z or x,z_1,...), HDF5 height map, a laser profilometer export or line "
                  "laser profiles (CSV line pairs), "
                  "recognised by its content")
      ->required();
  cmd->add_option("--out", options.out, "Output folder (default out/<input name>); written atomically");
  cmd->add_option("--set", options.overrides, "Override a key of the road: road.KEY=VALUE, value as TOML (TOML input only). Repeatable")
      ->allow_extra_args(false);  // one value per --set, so an input file after it stays the input
  cmd->add_option("--length", options.length, "Length of a generated road to analyse, m (default 7: bands to 500 mm)")
      ->check(positive_number());
  cmd->add_option("--spacing", options.spacing,
                  "Sample spacing of a generated road, m (default 0.0002; a texture road: its own sample_spacing)")
      ->check(positive_number())
      ->each([&options](const std::string&) { options.spacing_given = true; });
  cmd->add_option("--lines", options.lines, "Lateral lines of a generated road (default 1, the centre line)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--width", options.width, "Width over which the lines are spread, m (default 0.16)")
      ->check(positive_number());
  cmd->add_flag("--force", options.force,
                "Generate the road even when the estimate of its memory or output (--length / --spacing "
                "× --lines) exceeds what the machine has");
  cmd->footer(
      "Examples:\n"
      "  rollnoise road models/surfaces/dac11.toml --out out/dac11\n"
      "  rollnoise road data/surfaces/captif/20211011_aylesbury_dec_station_0.dat\n"
      "  rollnoise road data/surfaces/captif-transverse/20231114_cpx_demo.csv");
  return cmd;
}

int run_road(const RoadOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const fs::path input(options.input);
  std::error_code ec;
  if (!fs::is_regular_file(input, ec)) throw InputError(options.input, "", "file not found (or not a regular file)");
  const bool is_toml = input.extension() == ".toml";
  if (!is_toml && !options.overrides.empty()) {
    throw InputError(options.input, "--set", "applies to a TOML road; a profile file has no keys to set");
  }
  // ISO 13473-1's analysis takes profiles sampled at 1 mm or finer: say so of the option, before
  // any road is made.
  if (options.spacing_given && options.spacing > mpd_max_spacing_m) {
    throw InputError("command line", "--spacing",
                     "must be at most 0.001 m: the ISO 13473-1 analysis needs a sample spacing of at most 1 mm (got " +
                         format_number(options.spacing) + ")");
  }
  if (std::ceil(options.length / options.spacing) > static_cast<double>(max_profile_samples)) {
    throw InputError(options.input, "--length",
                     "--length / --spacing gives more than " + std::to_string(max_profile_samples) + " samples");
  }
  const fs::path out = options.out.empty() ? fs::path("out") / input.stem() : fs::path(options.out);
  if (is_toml) {
    // A generated road's size is set by the command line (up to max_profile_samples × 1000
    // lines, hundreds of GB): refused before it is sampled when it cannot fit. A profile file's
    // is bounded by its reader's limits (docs/reliability.md).
    const auto samples = static_cast<std::uint64_t>(std::floor(options.length / options.spacing)) + 1;
    check_run_fits(estimate_road_run(samples, static_cast<std::uint64_t>(options.lines), options.input),
                   available_memory_bytes(), available_disk_bytes(out), options.force);
  }
  RoadUnderTest road;
  if (is_toml) {
    road = generate(options);
  } else {
    road.profile = load_profile_file(input);
    road.description = "profile " + input.filename().string();
  }
  const LoadedProfile& p = road.profile;
  // The analysis names what is wrong (a profile sampled coarser than 1 mm, say); the file it
  // came from is the input's.
  const ProfileAnalysis analysis = [&] {
    try {
      return analyse_profile(p.z_lines, p.spacing_m);
    } catch (const InputError& error) {
      throw error.source().empty() ? error.with_source(options.input) : error;
    }
  }();

  StagedOutputDirectory staged(out);
  write_road_csv(staged.staging() / "road.csv", p);
  write_texture_csv(staged.staging() / "texture.csv", analysis.texture);
  if (!road.target.empty()) {
    std::ofstream target(staged.staging() / "target.csv");
    CsvWriter csv(target, {"wavelength_m", "Ltx_dB"});
    for (const auto& [w, l] : road.target) {
      const double row[] = {w, l};
      csv.row(row, 2);
    }
    close_output_file(target, staged.staging() / "target.csv");
  }
  nlohmann::json summary;
  summary["input"] = options.input;
  summary["road"] = road.description;
  summary["paths_outside_case_folder"] = road.paths_outside_folder;
  if (!road.about.is_null()) summary["about"] = road.about;
  summary["rms_m"] = analysis.rms_m;
  summary["skewness"] = analysis.skewness;
  if (analysis.mpd) {
    summary["mpd_m"] = analysis.mpd->mpd_m;
    summary["etd_m"] = analysis.mpd->etd_m;
    summary["mpd_segments"] = analysis.mpd->segments;
  } else {
    summary["mpd_m"] = nullptr;
    summary["etd_m"] = nullptr;
    summary["mpd_note"] = "the profile is shorter than one 100 mm segment (ISO 13473-1)";
  }
  summary["spikes_removed"] = p.spikes;
  summary["dropouts_filled"] = p.dropouts;
  if (analysis.unevenness) {
    summary["iso8608_class"] = analysis.unevenness->iso8608_class;
    summary["gd_n0_m3"] = analysis.unevenness->gd_n0;
  } else {
    summary["iso8608_class"] = nullptr;
    summary["iso8608_note"] = "the profile is too short for the ISO 8608 band (0.011-2.83 cycles/m)";
  }
  // Shortest wavelength first, as texture.csv.
  summary["texture"] = nlohmann::json::array();
  for (const TextureBand& b : analysis.texture)
    summary["texture"].push_back({{"wavelength_m", b.nominal_wavelength_m}, {"Ltx_dB", b.level_db}});
  summary["settings"] = {{"spacing_m", p.spacing_m},
                         {"samples_per_line", p.x.size()},
                         {"length_m", p.x.empty() ? 0.0 : p.x.back() - p.x.front()},
                         {"lines", p.z_lines.size()},
                         {"y_m", p.y}};
  summary["rollnoise_version"] = ROLLNOISE_VERSION;
  summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  plot_road(staged.staging(), road, !road.target.empty());
  write_text_file(staged.staging() / "summary.json", summary.dump(2) + "\n");
  staged.commit();
  char mpd[32] = "n/a";
  if (analysis.mpd) std::snprintf(mpd, sizeof mpd, "%.2f mm", analysis.mpd->mpd_m * 1000.0);
  std::printf("rollnoise: wrote %s (road.csv, texture.csv, summary.json and plots): MPD %s, RMS %.2f mm, skewness %+.2f\n",
              out.string().c_str(), mpd, analysis.rms_m * 1000.0, analysis.skewness);
  return 0;
}

}  // namespace rollnoise
