#include "simulation/point_contact_output.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "contact/point_contact.hpp"
#include "core/csv.hpp"
#include "core/gnuplot.hpp"
#include "core/output_directory.hpp"

namespace rollnoise {

void write_contact_csv(const std::filesystem::path& path, const ContactTrace& trace) {
  const Eigen::Index points = trace.force.cols();
  std::vector<std::string> header{"time"};
  for (Eigen::Index i = 1; i <= points; ++i) {
    const std::string id = std::to_string(i);
    header.insert(header.end(), {"road_" + id, "displacement_" + id, "force_" + id});
  }
  std::ofstream out(path, std::ios::binary);
  CsvWriter csv(out, header);
  std::vector<double> row(header.size());
  for (Eigen::Index n = 0; n < trace.time.size(); ++n) {
    row[0] = trace.time(n);
    for (Eigen::Index i = 0; i < points; ++i) {
      row[static_cast<std::size_t>(1 + 3 * i)] = trace.road(n, i);
      row[static_cast<std::size_t>(2 + 3 * i)] = trace.displacement(n, i);
      row[static_cast<std::size_t>(3 + 3 * i)] = trace.force(n, i);
    }
    csv.row(row.data(), row.size());
  }
  close_output_file(out, path);
}

nlohmann::json summarise_contact(const ContactTrace& trace) {
  nlohmann::json points = nlohmann::json::array();
  const auto samples = static_cast<double>(trace.time.size());
  for (Eigen::Index i = 0; i < trace.force.cols(); ++i) {
    const auto force = trace.force.col(i);
    const double in_contact = static_cast<double>((force.array() > 0.0).count());
    points.push_back({{"point", i + 1},
                      {"max_force_N", force.maxCoeff()},
                      {"mean_force_N", force.mean()},
                      {"contact_fraction", in_contact / samples},
                      {"min_gap_m", trace.gap.col(i).minCoeff()},
                      {"max_gap_m", trace.gap.col(i).maxCoeff()},
                      {"static_force_N", trace.preload_force(i)}});
  }
  return {{"points", points},
          {"min_gap_m", trace.gap.minCoeff()},
          {"indentation_m", trace.indentation},
          {"history_engine", trace.engine},
          {"lcp_iterations", summarise_iterations(trace.lcp_iterations)}};
}

nlohmann::json summarise_iterations(const std::vector<int>& per_step) {
  long total = 0;
  for (int v : per_step) total += v;
  return {{"total", total},
          {"max_per_step", per_step.empty() ? 0 : *std::max_element(per_step.begin(), per_step.end())},
          {"mean_per_step",
           per_step.empty() ? 0.0 : static_cast<double>(total) / static_cast<double>(per_step.size())}};
}

void plot_contact(const std::filesystem::path& dir, const ContactTrace& trace, const std::string& title) {
  const Eigen::Index points = trace.force.cols();
  // Mark the reference surface every few samples, as the paper's crosses do.
  const Eigen::Index every = std::max<Eigen::Index>(1, trace.time.size() / 150);
  std::ostringstream gp;
  gp << "# Drawn by rollnoise from contact.csv; run `gnuplot contact.gp` to redraw.\n"
     << "set terminal pngcairo size 1000," << (points > 1 ? 900 : 700) << " noenhanced font 'DejaVu Sans,10'\n"
     << "set output 'contact.png'\n"
     << "set datafile separator ','\n"
     << "set grid\nset key top right\n"
     << "set multiplot layout " << points + 1 << ",1 title \"" << title << "\"\n"
     << "set xlabel 'time (s)'\n";
  for (Eigen::Index i = 1; i <= points; ++i) {
    const Eigen::Index road = 2 + 3 * (i - 1);
    gp << "set ylabel 'point " << i << ": height (mm)'\n"
       << "plot 'contact.csv' using 1:($" << road + 1 << "*1e3) with lines lw 2 lc rgb '#1f77b4' title 'contact point " << i
       << "', \\\n     '' using 1:($" << road << "*1e3) every " << every
       << " with points pt 2 ps 0.6 lc rgb '#d62728' title 'reference surface'\n";
  }
  gp << "set ylabel 'contact force (N)'\nplot ";
  for (Eigen::Index i = 1; i <= points; ++i) {
    gp << (i > 1 ? ", \\\n     " : "") << "'contact.csv' using 1:" << 4 + 3 * (i - 1)
       << " with lines lw 1.5 title 'force " << i << "'";
  }
  gp << "\nunset multiplot\n";
  write_plot(dir, "contact", gp.str());
}

}  // namespace rollnoise
