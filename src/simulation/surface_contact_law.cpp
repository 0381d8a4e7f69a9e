#include "simulation/surface_contact_law.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "contact/halfspace_load_path.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/hdf5_writer.hpp"
#include "core/output_directory.hpp"
#include "road/road_surface.hpp"

namespace rollnoise {
namespace {

// The approaches at which every cell's law is read: ten a decade from 10 nm to 10 mm (a fine
// asphalt's cells reach full contact at tenths of a millimetre, a chip seal's at millimetres).
constexpr int kPerDecade = 10;
constexpr double kFirstApproach = 1e-8;
constexpr int kApproaches = 6 * kPerDecade + 1;

double grid_approach(int a) { return kFirstApproach * std::pow(10.0, static_cast<double>(a) / kPerDecade); }

// The value below which a fraction q of `values` lies (linear between order statistics).
double percentile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  const double at = q * static_cast<double>(values.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(at));
  const std::size_t j = std::min(i + 1, values.size() - 1);
  return values[i] + (values[j] - values[i]) * (at - static_cast<double>(i));
}

}  // namespace

SurfaceContactLaw surface_contact_law(const RoadSurface& road, double length, double width,
                                      const SurfaceContactLawOptions& options, const std::string& source,
                                      const std::string& key) {
  SurfaceContactLaw out;
  out.options = options;
  const double dx = options.cell_dx, dy = options.cell_dy;
  out.pixels = cell_pixels(dx, dy, road.sample_spacing(), source, key);
  ContactCellGrid grid;
  grid.dx = dx;
  grid.dy = dy;
  grid.x0 = 0.5 * dx;
  grid.step = dx;
  grid.positions = static_cast<std::size_t>(std::floor(length / dx * (1.0 + 1e-12)));
  const auto lines = static_cast<std::size_t>(std::floor(width / dy * (1.0 + 1e-12)));
  if (grid.positions == 0 || lines == 0)
    throw InputError(source, "--cell", "a cell of " + format_number(dx) + " m × " + format_number(dy) +
                                           " m does not fit the road's " + format_number(length) + " m × " +
                                           format_number(width) + " m");
  for (std::size_t j = 0; j < lines; ++j) grid.lines.push_back(-0.5 * width + (static_cast<double>(j) + 0.5) * dy);
  const std::size_t cells = grid.positions * lines;
  for (std::size_t m = 0; m < grid.positions; ++m)
    for (std::size_t j = 0; j < lines; ++j) {
      out.cell_x_m.push_back(grid.x0 + static_cast<double>(m) * grid.step);
      out.cell_y_m.push_back(grid.lines[j]);
    }
  const double cap = contact_law_force_cap(dx, dy, options.rubber);
  out.punch_compliance = cell_punch_compliance(grid, out.pixels, options.rubber);
  out.laws = std::make_shared<CellContactLaws>(cells, cap, 1e-3 * out.punch_compliance);
  // Each cell's force and contact at the approach grid, and the approach at its table's end.
  std::vector<double> force(cells * kApproaches), end(cells);
  std::vector<int> contacts(cells * kApproaches);
  for_each_cell_path(read_cell_heights(road, grid, out.pixels), grid, out.pixels, options.rubber, cap, options.threads,
                     [&](std::size_t cell, const std::vector<LoadPathPoint>& path, double top) {
                       set_law_from_path(*out.laws, cell, path, top, out.punch_compliance);
                       for (int a = 0; a < kApproaches; ++a) {
                         const PathState s = state_at_approach(path, grid_approach(a));
                         force[cell * kApproaches + static_cast<std::size_t>(a)] = s.force;
                         contacts[cell * kApproaches + static_cast<std::size_t>(a)] = s.contacts;
                       }
                       end[cell] = path.back().approach;
                     });
  const double last = *std::min_element(end.begin(), end.end());
  const double pixel_area = dx * dy / static_cast<double>(out.pixels.nx * out.pixels.ny);
  std::vector<double> column(cells);
  for (int a = 0; a < kApproaches && grid_approach(a) <= last; ++a) {
    double sum = 0.0, area = 0.0;
    for (std::size_t c = 0; c < cells; ++c) {
      column[c] = force[c * kApproaches + static_cast<std::size_t>(a)];
      sum += column[c];
      area += contacts[c * kApproaches + static_cast<std::size_t>(a)] * pixel_area;
    }
    out.approach_m.push_back(grid_approach(a));
    out.force_n.push_back(sum / static_cast<double>(cells));
    out.area_m2.push_back(area / static_cast<double>(cells));
    out.force_p10_n.push_back(percentile(column, 0.1));
    out.force_p90_n.push_back(percentile(column, 0.9));
  }
  return out;
}

void write_surface_contact_law(const std::filesystem::path& folder, const SurfaceContactLaw& law) {
  {
    const auto path = folder / "contact_law.csv";
    std::ofstream out(path);
    out << "# the mean law of " << law.cell_x_m.size() << " cells of " << format_number(law.options.cell_dx) << " m x "
        << format_number(law.options.cell_dy) << " m; tread E = " << format_number(law.options.rubber.youngs_modulus)
        << " Pa, nu = " << format_number(law.options.rubber.poisson_ratio)
        << "; approach from each cell's first touch; a tyre adds approach - c_punch * force, c_punch = "
        << format_number(law.punch_compliance) << " m/N\n";
    CsvWriter csv(out, {"approach_m", "force_N", "contact_area_m2", "force_p10_N", "force_p90_N"});
    for (std::size_t a = 0; a < law.approach_m.size(); ++a) {
      const double row[] = {law.approach_m[a], law.force_n[a], law.area_m2[a], law.force_p10_n[a], law.force_p90_n[a]};
      csv.row(row, 5);
    }
    close_output_file(out, path);
  }
  Hdf5Writer h5(folder / "contact_laws.h5");
  const auto vec = [](const std::vector<double>& v) { return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())).eval(); };
  const CellContactLaws& laws = *law.laws;
  h5.attribute("/", "tread_youngs_modulus_Pa", law.options.rubber.youngs_modulus);
  h5.attribute("/", "tread_poisson_ratio", law.options.rubber.poisson_ratio);
  h5.attribute("/", "cell_dx_m", law.options.cell_dx);
  h5.attribute("/", "cell_dy_m", law.options.cell_dy);
  h5.integer_attribute("/", "pixels_along", static_cast<std::int64_t>(law.pixels.nx));
  h5.integer_attribute("/", "pixels_across", static_cast<std::int64_t>(law.pixels.ny));
  h5.attribute("/", "punch_compliance_m_per_N", law.punch_compliance);
  h5.attribute("/", "force_cap_N", laws.force_cap());
  h5.group("mean");
  h5.write("mean/approach_m", vec(law.approach_m), "m", "approach from each cell's first touch");
  h5.write("mean/force_N", vec(law.force_n), "N", "mean force over the cells");
  h5.write("mean/contact_area_m2", vec(law.area_m2), "m^2", "mean area in contact over the cells");
  h5.write("mean/force_p10_N", vec(law.force_p10_n), "N", "10th percentile of the force over the cells");
  h5.write("mean/force_p90_N", vec(law.force_p90_n), "N", "90th percentile of the force over the cells");
  h5.group("cells");
  Eigen::VectorXd levels(CellContactLaws::levels);
  for (int k = 0; k < CellContactLaws::levels; ++k) levels(k) = laws.force_level(k);
  h5.write("cells/x_m", vec(law.cell_x_m), "m", "cell centre along the road");
  h5.write("cells/y_m", vec(law.cell_y_m), "m", "cell centre across the road");
  h5.write("cells/first_touch_height_m", laws.tops(), "m", "the cell's highest pixel, where it meets the tread first");
  h5.write("cells/force_levels_N", levels, "N", "the forces of each cell's table");
  h5.write("cells/sub_cell_approach_m", laws.approach_table(), "m",
           "per cell and force level: the approach the texture adds in series with the tyre, approach - c_punch * force");
  h5.close();
}

}  // namespace rollnoise
