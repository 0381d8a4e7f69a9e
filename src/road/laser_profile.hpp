#pragma once
// Profiles of a stationary laser profilometer (the CAPTIF SLP text format, see
// data/surfaces/captif/README.md): a header block of `key<TAB>value` lines, a line
// `*****DATA*****`, a column header `Data Point No:<TAB>Distance (mm)<TAB>Depth (mm)`, then one
// tab-separated row per point; `NaN` (or an empty field) where the laser saw nothing.
//
// Sign: the format's "Depth (mm)" column grows upwards. The instrument's reference plates,
// which stand well above the road at both ends of every record, read about +47 mm against a
// road at about 0 (CAPTIF's own software likewise treats values above +30 mm as plate), so
// height = +depth; height = -depth would put the plates 47 mm below the road they stand on,
// and the MPD would be taken over the valleys instead of the peaks.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rollnoise {

// A sample belongs to a reference plate when its height differs from the median height of the
// record by more than this (the plates stand ~47 mm proud; road texture and unevenness over
// a 2 m record stay within about ±10 mm of the median)...
inline constexpr double laser_plate_min_height_m = 20e-3;
// ... and lies in a run of such samples (dropouts taking the state of the valid sample
// before them) at least this long: an isolated wild value is a spike, not a plate.
inline constexpr double laser_plate_min_run_m = 1e-3;
// Road kept clear of each plate's edge (the laser's footprint and the plate's bevel).
inline constexpr double laser_plate_buffer_m = 2e-3;
// Largest input accepted (64 MiB: ~2.5 million rows, a 90 m record): bounds the memory.
inline constexpr std::size_t laser_max_bytes = std::size_t{64} << 20;

struct MeasuredProfile {
  std::vector<double> z_m;     // heights (m, z up) of the road between the plates, cleaned
  double spacing_m = 0;        // mean distance between rows
  std::string source;          // the file (or the name given to parse_laser_profile)
  std::size_t dropouts = 0;    // in the kept road part, before cleaning
  std::size_t spikes = 0;      // in the kept road part (see clean_profile)
  std::size_t trimmed_points = 0;  // rows cut off at the two ends (plates, beyond, buffers)
};

// Reads the stationary laser profilometer text format: header block, `*****DATA*****`,
// column header, rows; depth mm -> height m (see "Sign" above), detects and trims the
// reference plates at both ends by their height (a record without plates is kept whole; one
// with a single plate is trimmed at that end), then clean_profile(). Any problem is an
// InputError naming the file. Must survive arbitrary bytes (never crash, never allocate
// unbounded: inputs over laser_max_bytes are refused).
MeasuredProfile read_laser_profile(const std::filesystem::path& path);
MeasuredProfile parse_laser_profile(std::string_view text, const std::string& source);

// True when the text looks like this format (for content-based format detection): within its
// first 64 KiB a line starting `*****DATA*****`, followed by a column header naming
// "Distance (mm)" and "Depth (mm)".
bool looks_like_laser_profile(std::string_view text);

}  // namespace rollnoise
