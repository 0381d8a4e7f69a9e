#include "road_command.hpp"

#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "core/error.hpp"
#include "simulation/road_run.hpp"
#include "number_checks.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

CLI::App* add_road_command(CLI::App& app, RoadOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "road",
      "Generate or read a road and analyse it: mean profile depth and ETD (ISO 13473-1), the third-octave\n"
      "texture spectrum (ISO 13473-4) and the unevenness class (ISO 8608). Writes road.csv, texture.csv,\n"
      "summary.json, road.png and texture.png (with their gnuplot scripts); for a surface with [absorption],\n"
      "absorption.csv (normal-incidence absorption and impedance per third-octave band).");
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
      ->check(positive_number())
      ->each([&options](const std::string&) { options.width_given = true; });
  cmd->add_flag("--contact-law", options.contact_law,
                "Also compute the contact law a tyre meets: cells --cell DX,DY tiled over --length x --width, "
                "each the tread rubber (--tread-modulus, --tread-poisson) pressed onto the texture inside it; "
                "writes contact_law.csv (the mean law and its spread) and contact_laws.h5 (every cell's table)");
  cmd->add_option("--tread-modulus", options.tread_modulus, "Young's modulus of the tread rubber, Pa (with --contact-law)")
      ->check(positive_number());
  cmd->add_option("--tread-poisson", options.tread_poisson, "Poisson ratio of the tread rubber (default 0.48)")
      ->check(CLI::Range(-0.999, 0.499));
  cmd->add_option("--cell", options.cell, "Contact cell DX,DY along and across the road, m (with --contact-law)")
      ->delimiter(',')
      ->expected(2)
      ->check(positive_number());
  cmd->add_option("--ground-effect", options.ground_effect,
                  "Also write ground_effect.csv: the level of a point source over this surface minus that over a rigid "
                  "road, per third-octave band 100 Hz-10 kHz, for the source height HS, horizontal distance D and "
                  "receiver height HR (m), all > 0")
      ->delimiter(',')
      ->expected(3);
  cmd->add_flag("--force", options.force,
                "Generate the road even when the estimate of its memory or output (--length / --spacing "
                "× --lines) exceeds what the machine has");
  cmd->footer(
      "Examples:\n"
      "  rollnoise road models/surfaces/dac11.toml --out out/dac11\n"
      "  rollnoise road data/surfaces/captif/20211011_aylesbury_dec_station_0.dat\n"
      "  rollnoise road data/surfaces/captif-transverse/20231114_cpx_demo.csv\n"
      "  rollnoise road models/surfaces/dac11.toml --length 1 --contact-law --tread-modulus 4e6 --cell 0.00194,0.007\n"
      "  rollnoise road models/surfaces/pa16.toml --ground-effect 0.05,7.5,1.2");
  return cmd;
}

int run_road(const RoadOptions& options) {
  const fs::path input(options.input);
  const fs::path out = options.out.empty() ? fs::path("out") / input.stem() : fs::path(options.out);
  RoadRunOptions run;
  run.input = options.input;
  run.overrides = options.overrides;
  run.length = options.length;
  run.spacing = options.spacing;
  run.spacing_given = options.spacing_given;
  run.lines = options.lines;
  run.width = options.width;
  run.force = options.force;
  run.width_given = options.width_given;
  if (options.contact_law) {
    if (!(options.tread_modulus > 0.0))
      throw InputError("command line", "--tread-modulus", "is needed with --contact-law: the tread rubber's E, Pa");
    if (options.cell.size() != 2)
      throw InputError("command line", "--cell", "is needed with --contact-law: DX,DY of a contact cell, m");
    run.contact_law = SurfaceContactLawOptions{TreadRubber{options.tread_modulus, options.tread_poisson},
                                               options.cell[0], options.cell[1],
                                               static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))};
  } else if (options.tread_modulus > 0.0 || !options.cell.empty()) {
    throw InputError("command line", options.cell.empty() ? "--tread-modulus" : "--cell",
                     "applies to --contact-law only");
  }
  if (!options.ground_effect.empty())
    run.ground_effect = GroundEffectGeometry{options.ground_effect[0], options.ground_effect[1], options.ground_effect[2]};
  const RoadRun road = rollnoise::run_road(run, out);
  write_road_outputs(out, road);
  char mpd[32] = "n/a";
  if (road.analysis.mpd) std::snprintf(mpd, sizeof mpd, "%.2f mm", road.analysis.mpd->mpd_m * 1000.0);
  std::string extra = road.contact_law ? ", contact_law.csv, contact_laws.h5" : "";
  if (!road.absorption_bands.empty()) extra += ", absorption.csv";
  if (!road.ground_effect.empty()) extra += ", ground_effect.csv";
  std::printf("rollnoise: wrote %s (road.csv, texture.csv, summary.json and plots%s): MPD %s, RMS %.2f mm, skewness %+.2f\n",
              out.string().c_str(), extra.c_str(), mpd,
              road.analysis.rms_m * 1000.0, road.analysis.skewness);
  return 0;
}

}  // namespace rollnoise
