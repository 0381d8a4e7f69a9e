#pragma once
// Which reader a profile file needs, told from its content (not its name).
#include <filesystem>
#include <string_view>

namespace rollnoise {

enum class ProfileFormat {
  csv,      // text: a profile CSV (profile_csv.hpp) or a CSV height map
  hdf5,     // the HDF5 signature at offset 0, 512, 1024, ...: an HDF5 height map (height_map_hdf5.hpp)
  laser,    // a laser profilometer export (laser_profile.hpp: looks_like_laser_profile)
  line_laser,  // line laser profiles in CSV line pairs (line_laser_csv.hpp: looks_like_line_laser_csv)
  unknown,  // none of these (binary data that is not HDF5, an empty file)
};

// "csv", "hdf5", "laser profilometer", "line laser csv", "unknown".
std::string_view to_string(ProfileFormat format);

// Looks at the file's first bytes (1 MiB: a line laser file's first line of positions must end
// within them, about 25,000 positions): the HDF5 signature first, then the laser profilometer
// format, then the line laser pairs, then text (no NUL bytes, valid as CSV to look at: the CSV reader then says precisely
// what is wrong). A missing or unreadable file is an InputError naming it.
ProfileFormat detect_profile_format(const std::filesystem::path& path);

}  // namespace rollnoise
