#include "simulation/road_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

#include "core/cancellation.hpp"
#include "core/case_file.hpp"
#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/gnuplot.hpp"
#include "core/output_directory.hpp"
#include "core/regular_file.hpp"
#include "core/progress.hpp"
#include "road/mean_profile_depth.hpp"
#include "road/file_road.hpp"
#include "road/profile_surface_road.hpp"
#include "road/road_surface.hpp"
#include "road/texture_road.hpp"
#include "road/texture_spectrum.hpp"
#include "simulation/run_size.hpp"

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
  std::optional<SurfaceContactLaw> contact_law;
  RoadAbsorption absorption;
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
RoadUnderTest generate(const RoadRunOptions& options) {
  const fs::path path(options.input);
  const toml::table raw = options.toml ? *options.toml : parse_toml_file(path);
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
    file.emplace(CaseFile::from_table(path, raw, overrides));
  } else {
    // A surface file: the keys of a [road] table at the top level. --set road.key=... applies.
    std::vector<std::string> top_level;
    for (const std::string& o : overrides) top_level.push_back(o.rfind("road.", 0) == 0 ? o.substr(5) : o);
    file.emplace(CaseFile::model_from_table(path, raw, top_level));
  }
  const ConfigTable road = is_case ? file->section("road") : file->top();
  const toml::table& road_toml = is_case ? *file->root()["road"].as_table() : file->root();
  RoadUnderTest out;
  if (const toml::table* about = road_toml["about"].as_table()) out.about = toml_to_json(*about);
  const double half_width = options.lines > 1 || options.contact_law ? options.width / 2.0 : 0.0;
  const std::unique_ptr<RoadSurface> surface = make_road_surface(road, 0.0, options.length, half_width);
  if (options.contact_law)
    out.contact_law = surface_contact_law(*surface, options.length, options.width, *options.contact_law,
                                          road.source_of("sample_spacing"), "[road] sample_spacing");
  if (road_toml["type"].value_or(std::string()) == "texture") out.target = texture_target(road_toml);
  // A surface from measured lines shows the record's levels as its target.
  if (const auto* measured = dynamic_cast<const ProfileSurfaceRoad*>(surface.get())) {
    for (std::size_t b = 0; b < measured->record().nominal_m.size(); ++b)
      out.target.emplace_back(measured->record().nominal_m[b], measured->record().levels_db[b]);
  }
  out.description = surface->type() + " road from " + path.string();
  out.absorption = surface->absorption();

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
  ProgressReporter progress("sampling the road", static_cast<std::size_t>(options.lines) * samples, {}, true,
                            options.progress_sink);
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

// The analysis and summary.json of a road ready for it.
RoadRun analyse(RoadUnderTest road, const std::string& input, const std::optional<GroundEffectGeometry>& ground_effect,
                std::chrono::steady_clock::time_point started) {
  RoadRun run;
  const LoadedProfile& p = road.profile;
  // The analysis names what is wrong (a profile sampled coarser than 1 mm, say); the file it
  // came from is the input's.
  try {
    run.analysis = analyse_profile(p.z_lines, p.spacing_m);
  } catch (const InputError& error) {
    throw error.source().empty() ? error.with_source(input) : error;
  }
  const ProfileAnalysis& analysis = run.analysis;
  nlohmann::json summary;
  summary["input"] = input;
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
  if (road.contact_law) {
    const SurfaceContactLaw& law = *road.contact_law;
    summary["contact_law"] = {{"cells", law.cell_x_m.size()},
                              {"cell_dx_m", law.options.cell_dx},
                              {"cell_dy_m", law.options.cell_dy},
                              {"pixels_along", law.pixels.nx},
                              {"pixels_across", law.pixels.ny},
                              {"road_samples_per_pixel", law.pixels.samples},
                              {"tread_youngs_modulus_Pa", law.options.rubber.youngs_modulus},
                              {"tread_poisson_ratio", law.options.rubber.poisson_ratio},
                              {"punch_compliance_m_per_N", law.punch_compliance}};
  }
  // The surface's acoustics: its absorption when it has any, its ground effect when asked.
  if (!road.absorption.rigid()) {
    run.absorption_bands = absorption_bands(road.absorption);
    summary["absorption"] = absorption_summary(road.absorption, run.absorption_bands);
  }
  if (ground_effect) {
    run.ground_effect = ground_effect_bands(road.absorption, *ground_effect);
    summary["ground_effect"] = ground_effect_summary(*ground_effect, run.ground_effect);
    if (road.absorption.rigid()) summary["ground_effect"]["note"] = "a rigid surface: no change from the rigid road";
  }
  summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  run.summary = std::move(summary);
  run.absorption = std::move(road.absorption);
  run.profile = std::move(road.profile);
  run.description = std::move(road.description);
  run.target = std::move(road.target);
  run.contact_law = std::move(road.contact_law);
  return run;
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

void write_texture_csv(const fs::path& path, const std::vector<std::pair<double, double>>& bands) {
  std::ofstream out(path);
  CsvWriter csv(out, {"wavelength_m", "Ltx_dB"});
  for (const auto& [wavelength, level] : bands) {
    const double row[] = {wavelength, level};
    csv.row(row, 2);
  }
  close_output_file(out, path);
}

void plot_road(const fs::path& dir, const RoadRun& road, bool with_target) {
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

RoadRun run_road(const RoadRunOptions& options, const fs::path& out) {
  const auto started = std::chrono::steady_clock::now();
  const fs::path input(options.input);
  if (!options.toml) require_regular_file(options.input);
  const bool is_toml = options.toml || input.extension() == ".toml";
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
  if (options.ground_effect)
    check_ground_effect_geometry(*options.ground_effect, options.ground_effect_source, options.ground_effect_key);
  RoadUnderTest road;
  if (is_toml) {
    // A generated road's size is set by the command line (up to max_profile_samples × 1000
    // lines, hundreds of GB): refused before it is sampled when it cannot fit. A profile file's
    // is bounded by its reader's limits (docs/reliability.md).
    const auto samples = static_cast<std::uint64_t>(std::floor(options.length / options.spacing)) + 1;
    check_run_fits(estimate_road_run(samples, static_cast<std::uint64_t>(options.lines), options.input),
                   available_memory_bytes(), available_disk_bytes(out.empty() ? fs::path(".") : out), options.force);
    road = generate(options);
  } else {
    road.profile = load_profile_file(input);
    road.description = "profile " + input.filename().string();
    if (options.contact_law) {
      // A measured line has no width: it is used on every line across the cells, fully
      // correlated across (as a "file" road under a tyre), and only when the user says how wide.
      if (!options.width_given)
        throw InputError(options.input, "--contact-law",
                         "a profile file is one line without a width: give --width, over which the line is repeated "
                         "across, or make a surface from it ([road] type = \"profile_surface\")");
      const LoadedProfile& p = road.profile;
      const ProfileSurface surface(std::make_unique<FileRoad>(p.x, p.z_lines.front(), options.input));
      const double length = p.x.back() - p.x.front();
      road.contact_law = surface_contact_law(surface, length, options.width, *options.contact_law, options.input,
                                             "--contact-law");
    }
  }
  return analyse(std::move(road), options.input, options.ground_effect, started);
}

RoadRun run_road_heights(std::vector<std::vector<double>> z_lines, double spacing_m, std::vector<double> y,
                         const std::string& name) {
  const auto started = std::chrono::steady_clock::now();
  if (!(spacing_m > 0.0) || !std::isfinite(spacing_m))
    throw InputError(name, "spacing", "must be a positive number of metres (got " + format_number(spacing_m) + ")");
  if (z_lines.empty() || z_lines.front().empty()) throw InputError(name, "", "holds no heights");
  const std::size_t samples = z_lines.front().size();
  if (samples > max_profile_samples)
    throw InputError(name, "", "holds more than " + std::to_string(max_profile_samples) + " samples per line");
  if (y.empty()) {
    for (std::size_t j = 0; j < z_lines.size(); ++j) y.push_back(static_cast<double>(j));
  }
  if (y.size() != z_lines.size())
    throw InputError(name, "y", "gives " + std::to_string(y.size()) + " lateral positions for " +
                                    std::to_string(z_lines.size()) + " lines");
  std::vector<double> x(samples);
  for (std::size_t i = 0; i < samples; ++i) x[i] = static_cast<double>(i) * spacing_m;
  RoadUnderTest road;
  road.profile = make_uniform_profile(x, z_lines, std::move(y), name);
  clean_profile_lines(road.profile);
  road.description = "profile " + name;
  return analyse(std::move(road), name, std::nullopt, started);
}

void write_road_outputs(const fs::path& out, const RoadRun& road) {
  StagedOutputDirectory staged(out);
  write_road_csv(staged.staging() / "road.csv", road.profile);
  std::vector<std::pair<double, double>> texture;
  for (const TextureBand& b : road.analysis.texture) texture.emplace_back(b.nominal_wavelength_m, b.level_db);
  write_texture_csv(staged.staging() / "texture.csv", texture);
  if (!road.target.empty()) write_texture_csv(staged.staging() / "target.csv", road.target);
  if (road.contact_law) write_surface_contact_law(staged.staging(), *road.contact_law);
  if (!road.absorption_bands.empty()) write_absorption_csv(staged.staging() / "absorption.csv", road.absorption_bands);
  if (!road.ground_effect.empty()) write_ground_effect_csv(staged.staging() / "ground_effect.csv", road.ground_effect);
  plot_road(staged.staging(), road, !road.target.empty());
  write_text_file(staged.staging() / "summary.json", road.summary.dump(2) + "\n");
  staged.commit();
}

}  // namespace rollnoise
