#pragma once
// Profiles of a line laser, one CSV line pair per profile (the CAPTIF line-laser export, see
// data/surfaces/captif-transverse/README.md): no header; for each profile a line
//     <time stamp>,<position 1 (mm)>,<position 2 (mm)>,...,<position n (mm)>
// followed by a line with the same time stamp and the n heights:
//     <time stamp>,<height 1 (mm)>,<height 2 (mm)>,...,<height n (mm)>
// The time stamp is a number (the CAPTIF files write hhmmss.ffffff); positions are along the
// laser line (across the road for a transverse scan), strictly increasing (an uneven spacing is
// resampled by load_profile_file, as for a profile CSV);
// heights grow upwards (with this sign the shipped file's MPD is 0.48 mm, as the data's
// description says, about 0.5 mm; with the other it would be about 0.75 mm). An empty cell or NaN is a dropout
// (no reading). Every pair has the same positions: the lines are parallel scans of one laser
// line, which is how rollnoise exposes them (as the lines z_1 … z_n of a profile CSV).
//
// Not known from the file: how far apart the lines lie (the time stamps give their order, not
// the distance; the CAPTIF file's nine lines are a few centimetres apart along the road).
// load_profile_file (profile_file.hpp) labels them y = 0, 1, 2, … (the line's index, not a
// distance).
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rollnoise {

// Largest input accepted (64 MiB, as the other laser format): a number takes at least two bytes
// with its comma, so the parsed values need at most 4 times the text's size.
inline constexpr std::size_t line_laser_max_bytes = std::size_t{64} << 20;

struct LineLaserProfiles {
  std::vector<double> x_m;                  // positions along the laser line (m), common to all lines
  std::vector<std::vector<double>> z_lines; // heights (m, z up) per profile; NaN marks a dropout
  std::vector<double> time_stamps;          // each profile's time stamp as written
  std::string source;                       // the file (or the name given to the parser)
  std::size_t dropouts = 0;                 // over all lines
};

// Parses the format above. Any problem (an odd number of lines, time stamps of a pair that
// differ, a position or height line of another length than the first position line, a cell that
// is not a number, positions not increasing, positions that differ between pairs, a line whose
// heights are all dropouts) is an InputError naming `source` and the line.
// Must survive arbitrary bytes: never crash, never allocate unbounded (inputs over
// line_laser_max_bytes are refused).
LineLaserProfiles parse_line_laser_csv(std::string_view text, const std::string& source);
LineLaserProfiles read_line_laser_csv(const std::filesystem::path& path);

// True when `head` (the first bytes of a file) looks like this format, for content-based format
// detection: its first line is at least three comma-separated numbers (a time stamp and two
// positions), and the next line begins with the same time stamp field, followed by a comma.
// A profile CSV begins with a comment or a header of column names, so it never matches.
bool looks_like_line_laser_csv(std::string_view head);

}  // namespace rollnoise
