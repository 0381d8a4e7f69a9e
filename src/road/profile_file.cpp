#include "road/profile_file.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "road/height_map_hdf5.hpp"
#include "road/laser_profile.hpp"
#include "road/line_laser_csv.hpp"
#include "road/line_cleaning.hpp"
#include "road/profile_csv.hpp"
#include "road/profile_format.hpp"

namespace rollnoise {
namespace {

constexpr double uniform_tolerance = 1e-6;

double mean_spacing(const std::vector<double>& x) {
  return (x.back() - x.front()) / static_cast<double>(x.size() - 1);
}

}  // namespace

bool is_uniformly_spaced(const std::vector<double>& x) {
  if (x.size() < 2) return false;
  const double h = mean_spacing(x);
  if (!(h > 0.0) || !std::isfinite(h)) return false;
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (!(std::abs((x[i] - x[i - 1]) - h) <= uniform_tolerance * h)) return false;
  }
  return true;
}

LoadedProfile make_uniform_profile(const std::vector<double>& x, const std::vector<std::vector<double>>& z_lines,
                                   std::vector<double> y, const std::string& source) {
  LoadedProfile out;
  out.source = source;
  out.y = std::move(y);
  if (x.size() < 2) throw InputError(source, "", "needs at least 2 samples along x");
  if (!std::isfinite(x.back() - x.front())) throw InputError(source, "", "the x values span more than the largest number");
  if (is_uniformly_spaced(x)) {
    out.spacing_m = mean_spacing(x);
    out.x.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) out.x[i] = x.front() + static_cast<double>(i) * out.spacing_m;
    out.z_lines = z_lines;
    return out;
  }
  // The median interval.
  std::vector<double> steps(x.size() - 1);
  for (std::size_t i = 1; i < x.size(); ++i) steps[i - 1] = x[i] - x[i - 1];
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
  const double h = steps[steps.size() / 2];
  const double count = std::floor((x.back() - x.front()) / h * (1.0 + 1e-12)) + 1.0;
  if (!(h > 0.0) || !(count <= static_cast<double>(max_profile_samples))) {
    throw InputError(source, "",
                     "resampling the unevenly spaced x (from " + format_number(x.front()) + " to " +
                         format_number(x.back()) + " m) at its median interval " + format_number(h) +
                         " m would need more than " + std::to_string(max_profile_samples) + " samples");
  }
  const auto n = static_cast<std::size_t>(count);
  out.spacing_m = h;
  out.x.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.x[i] = std::min(x.front() + static_cast<double>(i) * h, x.back());
  for (const auto& z : z_lines) {
    std::vector<double> line(n);
    std::size_t k = 0;  // x[k] <= out.x[i] < x[k + 1]
    for (std::size_t i = 0; i < n; ++i) {
      const double xi = out.x[i];
      while (k + 2 < x.size() && x[k + 1] <= xi) ++k;
      const double f = (xi - x[k]) / (x[k + 1] - x[k]);
      if (f == 0.0) {
        line[i] = z[k];
      } else if (f == 1.0) {
        line[i] = z[k + 1];
      } else {
        line[i] = (1.0 - f) * z[k] + f * z[k + 1];  // NaN when either neighbour is a dropout
      }
    }
    out.z_lines.push_back(std::move(line));
  }
  return out;
}

LoadedProfile load_profile_file(const std::filesystem::path& path) {
  const std::string source = path.string();
  LoadedProfile out;
  switch (detect_profile_format(path)) {
    case ProfileFormat::csv: {
      const ProfileTable table = read_profile_csv(path);
      out = make_uniform_profile(table.x, table.z_lines, table.y, source);
      break;
    }
    case ProfileFormat::hdf5: {
      const HeightMapGrid grid = read_height_map_hdf5(path);
      const std::size_t nx = grid.x.size();
      const std::size_t ny = grid.y.size();
      std::vector<std::vector<double>> lines(ny, std::vector<double>(nx));
      for (std::size_t i = 0; i < nx; ++i)
        for (std::size_t j = 0; j < ny; ++j) lines[j][i] = grid.z[i * ny + j];
      out = make_uniform_profile(grid.x, lines, grid.y, source);
      break;
    }
    case ProfileFormat::laser: {
      // Read, trimmed of its reference plates and cleaned by its reader: on a uniform grid.
      MeasuredProfile laser = read_laser_profile(path);
      out.source = laser.source;
      out.spacing_m = laser.spacing_m;
      out.x.resize(laser.z_m.size());
      for (std::size_t i = 0; i < out.x.size(); ++i) out.x[i] = static_cast<double>(i) * laser.spacing_m;
      out.z_lines.push_back(std::move(laser.z_m));
      out.y = {0.0};
      out.dropouts = laser.dropouts;
      out.spikes = laser.spikes;
      return out;
    }
    case ProfileFormat::line_laser: {
      LineLaserProfiles lines = read_line_laser_csv(path);
      // x from 0 at the first position, as for the laser profilometer (the file's positions are
      // the sensor's, centred on it: a road's x starts at 0, and x < 0 is the flat lead-in).
      const double first = lines.x_m.front();
      for (double& x : lines.x_m) x -= first;
      // The lines' order is the file's; their distance apart is unknown: y is the index.
      std::vector<double> y(lines.z_lines.size());
      for (std::size_t j = 0; j < y.size(); ++j) y[j] = static_cast<double>(j);
      out = make_uniform_profile(lines.x_m, lines.z_lines, std::move(y), source);
      break;
    }
    case ProfileFormat::unknown:
      throw InputError(source, "",
                       "is not a profile file this program reads: a profile CSV (columns x and z, or "
                       "x and z_1, z_2, ...), an HDF5 height map (/x, /y, /z), a laser profilometer export "
                       "or line laser profiles (CSV line pairs: time stamp and positions, time stamp and heights)");
  }
  clean_profile_lines(out);
  return out;
}

void clean_profile_lines(LoadedProfile& out) {
  for (std::size_t line = 0; line < out.z_lines.size(); ++line) {
    const std::string where =
        out.z_lines.size() == 1 ? out.source : out.source + " (line " + std::to_string(line + 1) + ")";
    const LineCleaning cleaning = clean_measured_line(out.z_lines[line], out.spacing_m, where);
    out.dropouts += cleaning.dropouts;
    out.spikes += cleaning.spikes;
  }
}

}  // namespace rollnoise
