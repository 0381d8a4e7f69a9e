#pragma once
// A road analysed as road engineers do (what `rollnoise road` and the Python module's
// rollnoise.road call): generated from a [road] table (a case's, or a surface file's keys at the
// top level) on lines across the road, or read from a profile file, or given as heights; then
// RMS, MPD and ETD (ISO 13473-1), the third-octave texture spectrum (ISO 13473-4) and the ISO
// 8608 class (road/profile_analysis.hpp). The result is in memory; write_road_outputs writes
// road.csv, texture.csv, target.csv, summary.json and the plots into a folder, atomically.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "core/referenced_file.hpp"
#include "road/profile_analysis.hpp"
#include "road/profile_file.hpp"
#include "simulation/road_acoustics.hpp"
#include "simulation/surface_contact_law.hpp"

namespace rollnoise {

class ProgressSink;

struct RoadRunOptions {
  // The input: a file (TOML, told by its name ending in .toml, or a profile file told by its
  // content), named in messages and summary.json's `input`.
  std::string input;
  // A TOML road given in memory instead of the file `input` (which then only names it; library
  // files it names are found from its folder, or the current folder for a bare name).
  std::optional<toml::table> toml;
  std::vector<std::string> overrides;  // road.KEY=VALUE (KEY=VALUE for a surface file); TOML only
  double length = 7.0;                 // m, of a generated road
  double spacing = 0.0002;             // m, of a generated road
  bool spacing_given = false;          // else a texture road takes its own sample_spacing
  int lines = 1;                       // lateral lines of a generated road
  double width = 0.16;                 // m, over which the lines are spread
  bool force = false;                  // generate even when the estimate exceeds the machine
  bool width_given = false;            // --width was given (a profile file's contact law needs it)
  // The contact law of cells tiled over the road (surface_contact_law.hpp), over `width` and
  // `length`; a profile file's line is used across the width.
  std::optional<SurfaceContactLawOptions> contact_law;
  // The ground effect of the surface on a point source at this geometry (road_acoustics.hpp),
  // and how a bad geometry's message names where it came from (Python: the input and its
  // `ground_effect` argument).
  std::optional<GroundEffectGeometry> ground_effect;
  std::string ground_effect_source = "command line";
  std::string ground_effect_key = "--ground-effect";
  ProgressSink* progress_sink = nullptr;
};

struct RoadRun {
  LoadedProfile profile;                          // the lines analysed, on one uniform grid
  std::string description;                        // "<type> road from <file>" or "profile <file>"
  std::vector<std::pair<double, double>> target;  // (wavelength m, L_tx dB) of a texture road
  ProfileAnalysis analysis;
  nlohmann::json summary;                         // what summary.json holds
  std::optional<SurfaceContactLaw> contact_law;   // with RoadRunOptions::contact_law
  RoadAbsorption absorption;                      // the surface's [road.absorption]; rigid for a profile file
  std::vector<AbsorptionBand> absorption_bands;   // an absorbing surface's, else empty
  std::vector<GroundEffectBand> ground_effect;    // with RoadRunOptions::ground_effect
};

// Generates or reads the road and analyses it. Bad input is an InputError naming the input (and
// the option or key). `out`: where the outputs will go, for the estimate of a generated road's
// size against the free disk (empty: the current folder).
RoadRun run_road(const RoadRunOptions& options, const std::filesystem::path& out = {});

// Heights given in memory: `z_lines[line][i]` at x = i·spacing_m (NaN a dropout), lines at `y`
// (empty: 0, 1, 2, ...), cleaned and analysed as a profile file's are. `name` names them.
RoadRun run_road_heights(std::vector<std::vector<double>> z_lines, double spacing_m, std::vector<double> y,
                         const std::string& name);

// Writes road.csv, texture.csv (target.csv for a texture road), summary.json and the plots into
// `out`, atomically (core/output_directory.hpp); with a contact law, contact_law.csv and
// contact_laws.h5; for an absorbing surface absorption.csv; with a ground effect
// ground_effect.csv.
void write_road_outputs(const std::filesystem::path& out, const RoadRun& road);

}  // namespace rollnoise
