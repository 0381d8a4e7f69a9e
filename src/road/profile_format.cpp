#include "road/profile_format.hpp"

#include <fstream>
#include <string>

#include "core/error.hpp"
#include "core/hdf5_reader.hpp"
#include "road/laser_profile.hpp"
#include "road/line_laser_csv.hpp"

namespace rollnoise {
namespace {

// Enough for the first line of a line laser file of some thousands of positions.
constexpr std::size_t head_bytes = 1024 * 1024;

bool looks_like_text(std::string_view head) {
  if (head.empty()) return false;
  for (char c : head) {
    const auto u = static_cast<unsigned char>(c);
    // Control characters other than tab, line feed, carriage return (and form feed) mark binary
    // data; bytes >= 0x80 may be UTF-8 (a µ in a unit, a BOM).
    if (u < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f') return false;
    if (u == 0x7f) return false;
  }
  return true;
}

}  // namespace

std::string_view to_string(ProfileFormat format) {
  switch (format) {
    case ProfileFormat::csv: return "csv";
    case ProfileFormat::hdf5: return "hdf5";
    case ProfileFormat::laser: return "laser profilometer";
    case ProfileFormat::line_laser: return "line laser csv";
    case ProfileFormat::unknown: break;
  }
  return "unknown";
}

ProfileFormat detect_profile_format(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(path.string(), "", "file not found (or not a regular file)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot be opened for reading");
  std::string head(head_bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (has_hdf5_signature(path)) return ProfileFormat::hdf5;
  if (looks_like_laser_profile(head)) return ProfileFormat::laser;
  if (looks_like_line_laser_csv(head)) return ProfileFormat::line_laser;
  if (looks_like_text(head)) return ProfileFormat::csv;
  return ProfileFormat::unknown;
}

}  // namespace rollnoise
