#pragma once
// Which reader a profile file needs, told from its content (not its name).
#include <filesystem>
#include <string_view>

namespace rollnoise {

enum class ProfileFormat {
  csv,      // text: a profile CSV (profile_csv.hpp) or a CSV height map
  hdf5,     // the HDF5 signature at offset 0, 512, 1024, ...: an HDF5 height map (height_map_hdf5.hpp)
  laser,    // a laser profilometer export (laser_profile.hpp: looks_like_laser_profile)
  unknown,  // none of these (binary data that is not HDF5, an empty file)
};

// "csv", "hdf5", "laser profilometer", "unknown".
std::string_view to_string(ProfileFormat format);

// Looks at the file's first bytes: the HDF5 signature first, then the laser profilometer
// format, then text (no NUL bytes, valid as CSV to look at: the CSV reader then says precisely
// what is wrong). A missing or unreadable file is an InputError naming it.
ProfileFormat detect_profile_format(const std::filesystem::path& path);

}  // namespace rollnoise
