#include "road/height_map_hdf5.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "core/child_process.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/hdf5_reader.hpp"
#include "road/profile_csv.hpp"

namespace rollnoise {
namespace {

// The factor from the dataset's `units` attribute to metres.
double units_of(const Hdf5Reader& file, const std::string& dataset) {
  const auto units = file.string_attribute(dataset, "units");
  if (!units) {
    throw InputError(file.source(), dataset,
                     "has no attribute \"units\"; add one: \"m\", \"mm\" or \"um\"");
  }
  const double scale = unit_to_metres(*units);
  if (scale == 0.0) {
    throw InputError(file.source(), dataset + " attribute units",
                     "unknown unit \"" + printable_excerpt(*units) + "\"; allowed units are \"m\", \"mm\" and \"um\"");
  }
  return scale;
}

std::vector<double> grid_axis(const Hdf5Reader& file, const std::string& dataset, std::size_t min_count) {
  Hdf5Array array = file.read_numbers(dataset, 1, max_height_map_values);
  const double scale = units_of(file, dataset);
  std::vector<double>& v = array.values;
  if (v.size() < min_count) {
    throw InputError(file.source(), dataset,
                     "has " + std::to_string(v.size()) + " values; at least " + std::to_string(min_count) + " needed");
  }
  for (std::size_t k = 0; k < v.size(); ++k) {
    v[k] *= scale;
    if (!std::isfinite(v[k])) {
      throw InputError(file.source(), dataset + "[" + std::to_string(k) + "]", "must be a finite number");
    }
    if (k > 0 && !(v[k] > v[k - 1])) {
      throw InputError(file.source(), dataset + "[" + std::to_string(k) + "]",
                       format_number(v[k]) + " m is not greater than the value before (" + format_number(v[k - 1]) +
                           " m); the grid lines must be strictly increasing");
    }
  }
  return std::move(v);
}

HeightMapGrid read_in_this_process(const std::filesystem::path& path) {
  const Hdf5Reader file(path);
  HeightMapGrid out;
  out.source = file.source();
  out.x = grid_axis(file, "/x", 2);
  out.y = grid_axis(file, "/y", 1);
  Hdf5Array z = file.read_numbers("/z", 2, max_height_map_values);
  const std::size_t nx = out.x.size();
  const std::size_t ny = out.y.size();
  const bool shaped = z.dims.size() == 2 && z.dims[0] == nx && z.dims[1] == ny;
  if (!shaped) {
    std::string shape;
    for (std::size_t d : z.dims) shape += (shape.empty() ? "" : " x ") + std::to_string(d);
    const bool transposed = z.dims.size() == 2 && z.dims[0] == ny && z.dims[1] == nx;
    throw InputError(out.source, "/z",
                     "has shape " + shape + "; it must be [x][y], " + std::to_string(nx) + " x " + std::to_string(ny) +
                         (transposed ? " (it looks transposed: [y][x])" : ""));
  }
  const double scale = units_of(file, "/z");
  for (std::size_t k = 0; k < z.values.size(); ++k) {
    double& v = z.values[k];
    if (std::isnan(v)) {
      ++out.dropouts;
      continue;
    }
    v *= scale;
    if (!std::isfinite(v)) {
      throw InputError(out.source, "/z[" + std::to_string(k / ny) + "][" + std::to_string(k % ny) + "]",
                       "must be a finite number, or NaN for a dropout");
    }
  }
  if (out.dropouts == z.values.size()) {
    throw InputError(out.source, "/z", "has no value at all (every value is NaN, a dropout)");
  }
  out.z = std::move(z.values);
  return out;
}

}  // namespace

HeightMapGrid read_height_map_hdf5(const std::filesystem::path& path) {
  const std::string source = path.string();
  // The HDF5 library can crash on a corrupted file: it reads in a child process (child_process.hpp).
  const std::string bytes = run_in_child_process(
      [&] {
        const HeightMapGrid grid = read_in_this_process(path);
        ChildResultWriter out;
        out.count(grid.x.size());
        out.count(grid.y.size());
        out.count(grid.dropouts);
        out.doubles(grid.x.data(), grid.x.size());
        out.doubles(grid.y.data(), grid.y.size());
        out.doubles(grid.z.data(), grid.z.size());
        return std::move(out.bytes());
      },
      source, "the HDF5 library", 3 * sizeof(std::uint64_t) + 3 * max_height_map_values * sizeof(double),
      time_to_read(path));
  HeightMapGrid grid;
  grid.source = source;
  ChildResultReader in(bytes, "height map");
  const std::uint64_t nx = in.count();
  const std::uint64_t ny = in.count();
  grid.dropouts = static_cast<std::size_t>(in.count());
  if (nx > max_height_map_values || ny > max_height_map_values || nx * ny > max_height_map_values) {
    throw std::runtime_error("height map: malformed result from the reading process");
  }
  grid.x.resize(static_cast<std::size_t>(nx));
  grid.y.resize(static_cast<std::size_t>(ny));
  grid.z.resize(static_cast<std::size_t>(nx * ny));
  in.doubles(grid.x.data(), grid.x.size());
  in.doubles(grid.y.data(), grid.y.size());
  in.doubles(grid.z.data(), grid.z.size());
  return grid;
}

}  // namespace rollnoise
