#include "simulation/run_size.hpp"

#include <cstdio>

namespace rollnoise {
namespace {

std::string count(std::uint64_t n) {
  char text[32];
  std::snprintf(text, sizeof text, n < 100000 ? "%.0f" : "%.3g", static_cast<double>(n));
  return text;
}

}  // namespace

RunEstimate estimate_point_run(std::uint64_t samples, std::uint64_t points, const std::string& source) {
  RunEstimate e;
  e.source = source;
  e.keys = {"[rolling] duration", "[rolling] time_step"};
  const std::string keys = "[rolling] duration, [rolling] time_step";
  const std::uint64_t cells = checked_product({samples, points}, source, keys);
  // Four samples × points fields of doubles (and the history the direct engine keeps, as large).
  e.memory_bytes = checked_product({cells, 5 * 8}, source, keys);
  // contact.csv: about 25 characters a number, 3 numbers a point and the time.
  e.disk_bytes = checked_sum({checked_product({cells, 3 * 25}, source, keys), checked_product({samples, 25}, source, keys)},
                             source, keys);
  e.what = count(samples) + " time steps × " + count(points) + " contact points";
  return e;
}

RunEstimate estimate_tyre_run(std::uint64_t samples, std::uint64_t window_points, std::uint64_t lateral,
                              std::uint64_t circumferential, std::uint64_t receivers, std::uint64_t audio_frames,
                              const std::string& source) {
  RunEstimate e;
  e.source = source;
  e.keys = {"[rolling] duration", "[rolling] band_top", "[rolling] contact_window", "[rolling] points_lateral",
            "[rolling] points_circumferential"};
  const std::string keys =
      "[rolling] duration, band_top, contact_window, points_lateral, points_circumferential";
  const std::uint64_t contact = checked_product({samples, window_points}, source, keys);
  const std::uint64_t belt = checked_product({samples, lateral, circumferential}, source, keys);
  // Memory: the contact trace (force, displacement, road: doubles) and the belt's velocity on
  // the radiation mesh, about as many points as the belt row by row (doubles, one step's worth
  // of rows per sample).
  e.memory_bytes = checked_sum({checked_product({contact, 3 * 8}, source, keys),
                                checked_product({samples, circumferential, 8}, source, keys)},
                               source, keys);
  // Disk: contact.h5 (three contact fields as doubles, two belt fields as floats) and the WAVs.
  e.disk_bytes = checked_sum({checked_product({contact, 3 * 8}, source, keys), checked_product({belt, 2 * 4}, source, keys),
                              checked_product({receivers, audio_frames, 4}, source, keys)},
                             source, keys);
  e.what = count(samples) + " time steps × " + count(window_points) + " contact points, belt of " + count(lateral) +
           " × " + count(circumferential) + " points";
  return e;
}

}  // namespace rollnoise
