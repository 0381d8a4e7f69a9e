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

RunEstimate estimate_tyre_run(const TyreRunSize& z, const std::string& source) {
  RunEstimate e;
  e.source = source;
  e.keys = {"[rolling] duration", "[rolling] band_top", "[rolling] contact_window", "[rolling] points_lateral",
            "[rolling] points_circumferential", "[output] fields"};
  const std::string keys =
      "[rolling] duration, band_top, contact_window, points_lateral, points_circumferential, [output] fields";
  // Memory: per step, the totals (six doubles, two counts), the road's column means, and the
  // belt's velocity on the radiation mesh, about as many points as the belt row by row.
  e.memory_bytes = checked_sum({checked_product({z.samples, 64}, source, keys),
                                checked_product({z.samples, z.window_columns, 8}, source, keys),
                                z.radiating ? checked_product({z.samples, z.circumferential, 8}, source, keys) : 0},
                               source, keys);
  // Disk: contact.h5 (floats) and the WAVs.
  std::uint64_t fields_per_step = 0;
  if (z.fields != ContactFields::none) {
    const std::uint64_t belt = checked_product({z.lateral, z.circumferential}, source, keys);
    const auto blocks = [](std::uint64_t cells, int block) { return (cells + static_cast<std::uint64_t>(block) - 1) / static_cast<std::uint64_t>(block); };
    const std::uint64_t surface = z.fields == ContactFields::all
                                      ? 2 * belt
                                      : blocks(z.lateral, z.block.across > 0 ? z.block.across : static_cast<int>(z.lateral)) *
                                            blocks(z.circumferential, z.block.around);
    // Force (and in "all" road and displacement) over the window; the road strip, about one
    // lateral row of heights per step, is counted with the belt's blocks.
    const std::uint64_t window_fields = z.fields == ContactFields::all ? 3 : 1;
    fields_per_step =
        checked_sum({checked_product({z.window_points, window_fields}, source, keys), surface, z.lateral}, source, keys);
  }
  e.disk_bytes = checked_sum({checked_product({z.samples, fields_per_step, 4}, source, keys),
                              checked_product({z.receivers, z.audio_frames, 4}, source, keys)},
                             source, keys);
  e.what = count(z.samples) + " time steps × " + count(z.window_points) + " contact points, belt of " +
           count(z.lateral) + " × " + count(z.circumferential) + " points, fields \"" + to_string(z.fields) + "\"";
  return e;
}

}  // namespace rollnoise
