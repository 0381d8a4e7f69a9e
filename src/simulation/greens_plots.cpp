#include "simulation/greens_plots.hpp"

#include <fstream>
#include <sstream>
#include <vector>

#include <Eigen/Core>

#include "core/csv.hpp"
#include "core/gnuplot.hpp"
#include "core/output_directory.hpp"
#include "greens/centre_line_response.hpp"

namespace rollnoise {

void write_greens_circumference(const std::filesystem::path& dir, const CentreLineResponse& response, int points,
                                PlotBatch* batch) {
  const double length = response.circumference();
  // 0.25, 0.5, 1 and 2 ms: samples 1, 3, 7 and 15 of a table at 0.125 ms (step means over
  // 0.125 ms for a model transformed from the frequency domain).
  const std::vector<int> at{1, 3, 7, 15};
  std::vector<double> x(static_cast<std::size_t>(points) + 1);
  for (int i = 0; i <= points; ++i) x[static_cast<std::size_t>(i)] = -0.5 * length + length * i / points;
  const Eigen::MatrixXd g = response.green_table(x, 0.125e-3, 16);
  {
    std::ofstream out(dir / "greens_circumference.csv", std::ios::binary);
    CsvWriter csv(out, {"x", "g_0.25ms", "g_0.5ms", "g_1ms", "g_2ms"});
    for (std::size_t i = 0; i < x.size(); ++i) {
      const auto c = static_cast<Eigen::Index>(i);
      const double row[5] = {x[i], g(at[0], c), g(at[1], c), g(at[2], c), g(at[3], c)};
      csv.row(row, 5);
    }
    close_output_file(out, dir / "greens_circumference.csv");
  }
  std::ostringstream gp;
  gp << "# The belt's Green's function along the circumference (cf. Larsson 2000, Fig. 5a).\n"
     << "set terminal pngcairo size 1000,500 noenhanced font 'DejaVu Sans,10'\n"
     << "set output 'greens_circumference.png'\nset datafile separator ','\nset grid\nset key top right\n"
     << "set title 'Green function of the " << response.model()
     << " along the circumference, unit impulse at x = 0 (mid-width)'\n"
     << "set xlabel 'position around the tyre, x (m)'\nset ylabel 'g (mm/(N s))'\n"
     << "plot for [c=2:5] 'greens_circumference.csv' using 1:(column(c)*1e3) with lines lw 1.5 "
        "title columnheader(c)\n";
  write_plot(dir, "greens_circumference", gp.str(), batch);
}

}  // namespace rollnoise
