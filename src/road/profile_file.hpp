#pragma once
// Loading any profile file into memory for analysis (what `rollnoise road PROFILE_FILE` calls):
// the format is told from the content (profile_format.hpp), the heights are cleaned per
// ISO 13473-1 (dropouts and spikes, line_cleaning.hpp), and every line is on one uniform x grid.
//
// Formats: a profile CSV (profile_csv.hpp: x,z or x,z_1..z_n with a y line); an HDF5 height
// map (height_map_hdf5.hpp: each y grid line becomes one height line along x); a laser
// profilometer export (laser_profile.hpp: read, trimmed of its reference plates and cleaned by
// read_laser_profile; x = i * spacing from the first sample kept); line laser profiles in CSV
// line pairs (line_laser_csv.hpp: each pair one line, z_1 … z_n in the file's order, x the
// positions along the laser line less the first one, so from 0; y = 0, 1, 2, … the line's
// index: the file does not say how far apart the lines lie).
//
// Uniform spacing: x is uniform when every interval is within 1e-6 (relative) of the mean
// interval; then x is replaced by x_0 + i * spacing (a change below 1e-6 of the spacing).
// Otherwise every line is resampled by linear interpolation onto x_0 + i * h, h the median
// interval, up to the last x (a sample next to a dropout stays a dropout), before cleaning.
// At most max_profile_samples samples per line.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rollnoise {

inline constexpr std::size_t max_profile_samples = std::size_t{1} << 26;

struct LoadedProfile {
  std::vector<double> x;                    // m, x_0 + i * spacing_m
  std::vector<std::vector<double>> z_lines; // m, z_lines[line][i], all finite
  std::vector<double> y;                    // m, the lateral position of each line
  double spacing_m = 0.0;
  std::string source;                       // the file
  std::size_t dropouts = 0;                 // samples filled, over all lines
  std::size_t spikes = 0;                   // samples replaced as spikes, over all lines
};

LoadedProfile load_profile_file(const std::filesystem::path& path);

// The uniform-grid step of load_profile_file on its own: `z_lines` sampled at the increasing
// `x` (NaN marks a dropout) put on a uniform grid as described above. `source` names the data
// in messages. Cleaning is not applied.
LoadedProfile make_uniform_profile(const std::vector<double>& x, const std::vector<std::vector<double>>& z_lines,
                                   std::vector<double> y, const std::string& source);

// The cleaning step of load_profile_file on its own: every line of `profile` cleaned per
// ISO 13473-1 (dropouts filled, spikes replaced), counted in `dropouts` and `spikes`.
void clean_profile_lines(LoadedProfile& profile);

// Whether the increasing `x` is uniform in the sense above.
bool is_uniformly_spaced(const std::vector<double>& x);

}  // namespace rollnoise
