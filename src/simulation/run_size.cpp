#include "simulation/run_size.hpp"

#include <algorithm>
#include <cstdio>

namespace rollnoise {
namespace {

std::string count(std::uint64_t n) {
  char text[32];
  std::snprintf(text, sizeof text, n < 100000 ? "%.0f" : "%.3g", static_cast<double>(n));
  return text;
}

}  // namespace

RunEstimate estimate_point_run(std::uint64_t samples, std::uint64_t points, std::uint64_t lags, const std::string& source) {
  RunEstimate e;
  e.source = source;
  e.keys = {"[rolling] duration", "[rolling] time_step"};
  const std::string keys = "[rolling] duration, [rolling] time_step";
  const std::uint64_t cells = checked_product({samples, points}, source, keys);
  // Four samples × points fields of doubles and the forces the engine keeps; the kernel's lags
  // twice (direct_history_engine.hpp: as made, and reversed side by side).
  const std::uint64_t kernel = checked_product({std::min(lags, samples), points, points, 2 * 8}, source, keys);
  e.memory_bytes = checked_sum({checked_product({cells, 5 * 8}, source, keys), kernel}, source, keys);
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
  // The direct engine's kernel grows with the square of the window and the run's length: when
  // it is held, the engine is the first key to change.
  if (z.direct_history) e.keys.insert(e.keys.begin(), "[rolling] history");
  const std::string keys =
      "[rolling] history, duration, band_top, contact_window, points_lateral, points_circumferential, [output] fields";
  // Memory: per step, the totals (six doubles, two counts), the road's column means, and the
  // belt's velocity on the radiation mesh, about as many points as the belt row by row: the
  // whole record, or when streamed one block of it and the block's spectra (about as large).
  const std::uint64_t radiating_rows = z.radiation_block > 0 ? 2 * std::min(z.radiation_block, z.samples) : z.samples;
  const std::uint64_t window_matrix = checked_product({z.window_points, z.window_points, 8}, source, keys);
  // The direct engine: the sheared kernel (one window matrix a step) as made and reversed, and
  // the forces of every step; the modal engine: a state, its decay, input and rate, and the
  // prediction per pole (complex), and the window's modal shapes.
  const std::uint64_t engine =
      z.direct_history
          ? checked_sum({checked_product({z.samples, window_matrix, 2}, source, keys),
                         checked_product({z.samples, z.window_points, 8}, source, keys)},
                        source, keys)
          : checked_product({z.modal_poles, 5 * 16}, source, keys);
  // The audio: each receiver's signal at the audio rate, resampled, looped and written (three
  // copies); over an absorbing road the pass-by's image filter holds its series' filtered copies
  // of the source (audio/moving_image_filter.hpp: 33 for the ISO geometry over porous asphalt,
  // counted as 40).
  const std::uint64_t audio =
      checked_product({checked_sum({checked_product({z.receivers, 3}, source, keys), z.absorbing_pass_by ? 40u : 0u}, source, keys),
                       z.audio_frames, 8},
                      source, keys);
  e.memory_bytes = checked_sum({checked_product({z.samples, 64}, source, keys),
                                checked_product({z.samples, z.window_columns, 8}, source, keys),
                                checked_product({window_matrix, 6}, source, keys), engine,
                                z.radiating ? checked_product({radiating_rows, z.circumferential, 8}, source, keys) : 0,
                                z.radiating ? z.radiation_solve_bytes : 0, audio},
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
  if (z.direct_history)
    e.what += "; the direct history engine holds " + format_bytes(engine) +
              " of kernel (history = \"auto\" takes the modal engine, a few MB)";
  return e;
}

std::uint64_t radiation_solve_bytes(const TyreRadiationSettings& settings, std::size_t threads) {
  TyreSurfaceMeshSpec finest = radiation_mesh_levels(settings).back().spec;
  finest.geometry = TyreGeometry::undeformed;
  const TyreSurfaceMesh mesh = make_tyre_surface_mesh(finest);
  return static_cast<std::uint64_t>(mesh.points.cols()) * static_cast<std::uint64_t>(mesh.sources.cols()) * 16u *
         std::max<std::uint64_t>(1, threads);
}

RunEstimate estimate_road_run(std::uint64_t samples, std::uint64_t lines, const std::string& source) {
  RunEstimate e;
  e.source = source;
  e.keys = {"--length", "--spacing", "--lines"};
  const std::string keys = "--length, --spacing, --lines";
  // The lines and x (doubles), and the analysis's working copies of one line at a time (the
  // detrended line and its spectrum: about four lines' worth).
  const std::uint64_t values = checked_product({samples, checked_sum({lines, 1, 4}, source, keys)}, source, keys);
  e.memory_bytes = checked_product({values, 8}, source, keys);
  // road.csv: about 25 characters a number, x and one number a line on each row.
  e.disk_bytes = checked_product({samples, checked_sum({lines, 1}, source, keys), 25}, source, keys);
  e.what = count(samples) + " samples × " + count(lines) + " lines";
  return e;
}

RunEstimate estimate_greens_run(std::uint64_t frequencies, std::uint64_t distances) {
  RunEstimate e;
  e.source = "command line";
  e.keys = {"--frequencies", "--distances"};
  const std::string keys = "--frequencies, --distances";
  const std::uint64_t cells = checked_product({frequencies, distances}, e.source, keys);
  // Receptance and mobility (complex doubles), and the real and imaginary copies for greens.h5.
  e.memory_bytes = checked_product({cells, 2 * 16 + 2 * 8}, e.source, keys);
  // receptance.csv and mobility.csv (four numbers a row, about 25 characters each) and greens.h5.
  e.disk_bytes = checked_product({cells, 2 * 4 * 25 + 16}, e.source, keys);
  e.what = count(frequencies) + " frequencies × " + count(distances) + " distances";
  return e;
}

RunEstimate estimate_calibration_run(std::uint64_t lines, std::uint64_t parameters, const std::string& source) {
  RunEstimate e;
  e.source = source;
  e.keys = {"--data", "--frequency-range"};
  const std::string keys = "--data, --frequency-range";
  // The Jacobian (two residuals a line, a column a parameter and one more for the residuals),
  // and per line the measured, fitted and weighted values (about 100 bytes).
  e.memory_bytes = checked_product(
      {lines, checked_sum({checked_product({2, checked_sum({parameters, 1}, source, keys), 8}, source, keys), 100},
                          source, keys)},
      source, keys);
  // fit.csv: 11 numbers a line, about 25 characters each.
  e.disk_bytes = checked_product({lines, 11 * 25}, source, keys);
  e.what = count(lines) + " measured lines, " + count(parameters) + " parameters";
  return e;
}

}  // namespace rollnoise
