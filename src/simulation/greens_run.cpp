#include "simulation/greens_run.hpp"

#include <chrono>
#include <cmath>
#include <complex>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/cancellation.hpp"
#include "core/case_file.hpp"
#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/gnuplot.hpp"
#include "core/hdf5_writer.hpp"
#include "core/output_directory.hpp"
#include "core/regular_file.hpp"
#include "greens/fitted_modal_tyre.hpp"
#include "core/cache_limit.hpp"
#include "greens/modal_table_cache.hpp"
#include "greens/modal_table_hdf5.hpp"
#include "simulation/greens_plots.hpp"
#include "simulation/run_size.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

std::vector<double> evenly_spaced(double a, double b, long long n) {
  std::vector<double> f(static_cast<std::size_t>(n));
  for (long long i = 0; i < n; ++i)
    f[static_cast<std::size_t>(i)] = n == 1 ? a : a + (b - a) * static_cast<double>(i) / static_cast<double>(n - 1);
  return f;
}

namespace {

// Frequencies given to the run: finite, at least 0, at most kMaxGreensFrequencies of them.
std::vector<double> checked_frequencies(const std::vector<double>& f) {
  if (f.size() > static_cast<std::size_t>(kMaxGreensFrequencies))
    throw InputError("command line", "--frequencies", "at most " + std::to_string(kMaxGreensFrequencies) + " frequencies");
  for (const double x : f)
    if (!std::isfinite(x) || x < 0.0) throw InputError("command line", "--frequencies", "must be finite numbers >= 0 (Hz)");
  return f;
}

std::vector<double> checked_distances(const GreensRunOptions& options, const CentreLineResponse& response) {
  std::vector<double> d = options.distances.empty() ? response.default_distances() : options.distances;
  if (d.size() > kMaxGreensDistances)
    throw InputError("command line", "--distances", "at most " + std::to_string(kMaxGreensDistances) + " distances");
  const double half = 0.5 * response.circumference();
  for (const double x : d) {
    std::ostringstream value;
    value << x;
    if (!std::isfinite(x)) throw InputError("command line", "--distances", "must be finite numbers (m)");
    if (response.circumference() > 0.0 && std::abs(x) > half + 1e-12)
      throw InputError("command line", "--distances",
                       value.str() + " m lies beyond half the circumference (" + std::to_string(half) + " m)");
    if (!response.has_point(x)) {
      std::ostringstream points;
      for (const double p : response.default_distances()) points << ' ' << p;
      throw InputError("command line", "--distances",
                       value.str() + " m is not a point of the " + response.model() + " model; its points are at" +
                           points.str() + " m");
    }
  }
  return d;
}

void write_table(const fs::path& path, const std::vector<double>& f, const std::vector<double>& d,
                 const Eigen::MatrixXcd& values) {
  std::ofstream out(path, std::ios::binary);
  CsvWriter csv(out, {"frequency_hz", "distance_m", "re", "im"});
  // Up to 1e9 rows, with the staging folder there: polled row by row, so that Ctrl-C removes
  // it (the watchdog would leave it behind).
  const CancellationToken cancel;
  // Distance by distance, so that each response point is one block of rows (and one line).
  for (std::size_t j = 0; j < d.size(); ++j)
    for (std::size_t i = 0; i < f.size(); ++i) {
      cancel.throw_if_cancelled();
      const std::complex<double> v = values(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
      const double row[] = {f[i], d[j], v.real(), v.imag()};
      csv.row(row, 4);
    }
  close_output_file(out, path);
}

// Point and transfer mobility against frequency: magnitude (dB re 1 m/(N·s)) and phase, one
// line per distance (selected by its value in column 2).
void plot_mobility(const fs::path& dir, const CentreLineResponse& response, const std::vector<double>& distances,
                   bool log_axis) {
  std::ostringstream magnitude, phase;
  for (std::size_t k = 0; k < distances.size(); ++k) {
    std::ostringstream select;
    select.precision(17);
    select << "(abs($2 - (" << distances[k] << ")) < 1e-9 ? ";
    const char* sep = k == 0 ? "plot " : ", \\\n     ";
    magnitude << sep << "'mobility.csv' using 1:" << select.str() << "20*log10(sqrt($3**2 + $4**2)) : 1/0) "
              << "with lines lw 1.5 title 'd = " << distances[k] << " m'";
    phase << sep << "'mobility.csv' using 1:" << select.str() << "atan2($4, $3)*180/pi : 1/0) with lines lw 1.5 notitle";
  }
  std::ostringstream gp;
  gp << "# Drawn by rollnoise greens from mobility.csv; run `gnuplot mobility.gp` to redraw.\n"
     << "set terminal pngcairo size 1000,750 noenhanced font 'DejaVu Sans,10'\n"
     << "set output 'mobility.png'\nset datafile separator ','\nset grid\nset key top right\n"
     << (log_axis ? "set logscale x\n" : "")
     << "set multiplot layout 2,1 title 'Mobility of the " << response.model()
     << ": force at x = 0, response at distance d along the circumference'\n"
     << "set ylabel '|Y| (dB re 1 m/(N s))'\n" << magnitude.str() << "\n"
     << "set xlabel 'frequency (Hz)'\nset ylabel 'phase (deg)'\nset yrange [-180:180]\nset ytics 90\n"
     << phase.str() << "\nunset multiplot\n";
  write_plot(dir, "mobility", gp.str());
}

// The free waves of a layered tyre (issue 11: its dispersion curves): |H_zz(m, n, f)| of the first
// lateral order over the circumferential wavenumber k_m and the frequency, from the modal
// table. Each free wave is a ridge of the map, k(f): the belt's flexural wave, the tread's
// thickness resonances and the Rayleigh-like wave of the rubber (dispersion.csv, .gp, .png).
void plot_dispersion(const fs::path& dir, const ModalReceptanceTable& table) {
  const int n = table.first_lateral_order;
  {
    std::ofstream out(dir / "dispersion.csv", std::ios::binary);
    CsvWriter csv(out, {"wavenumber_rad_per_m", "frequency_hz", "log10_abs_receptance_m_per_pa"});
    for (int m = 0; m <= table.orders; ++m) {
      const Eigen::VectorXcd& h = table.mode(m, n);
      for (Eigen::Index k = 0; k < h.size(); ++k) {
        if (table.frequency(k) < 20.0 || table.frequency(k) > 6000.0) continue;
        const double row[] = {table.wavenumber_x(m), table.frequency(k), std::log10(std::abs(h(k)))};
        csv.row(row, 3);
      }
      out << '\n';  // a blank line between orders: gnuplot's grid for pm3d
    }
    close_output_file(out, dir / "dispersion.csv");
  }
  std::ostringstream gp;
  gp << "# Drawn by rollnoise greens from dispersion.csv; run `gnuplot dispersion.gp` to redraw.\n"
     << "set terminal pngcairo size 1000,650 noenhanced font 'DejaVu Sans,10'\n"
     << "set output 'dispersion.png'\nset datafile separator ','\n"
     << "set title 'Free waves of the " << table.source << " tyre, lateral order n = " << n
     << ": log10 |H_zz|; its ridges are the dispersion curves'\n"
     << "set xlabel 'circumferential wavenumber k (rad/m)'\nset ylabel 'frequency (Hz)'\nset logscale y\n"
     << "set yrange [20:6000]\nset view map\nset pm3d map interpolate 1,1\nset palette rgb 33,13,10\n"
     << "set cblabel 'log10 |H_zz| (m/Pa)'\n"
     << "splot 'dispersion.csv' skip 1 using 1:2:3 with pm3d notitle\n";
  write_plot(dir, "dispersion", gp.str());
}

// A point model's Green's function against time at each of its points (green_time.csv, .gp, .png).
void write_green_against_time(const fs::path& dir, const CentreLineResponse& response, const Eigen::VectorXd& time,
                              const Eigen::MatrixXd& green, const std::vector<double>& points) {
  {
    std::vector<std::string> header{"time"};
    for (std::size_t j = 0; j < points.size(); ++j) header.push_back("g_" + std::to_string(j + 1));
    std::ofstream out(dir / "green_time.csv", std::ios::binary);
    CsvWriter csv(out, header);
    std::vector<double> row(points.size() + 1);
    for (Eigen::Index k = 0; k < time.size(); ++k) {
      row[0] = time(k);
      for (std::size_t j = 0; j < points.size(); ++j) row[j + 1] = green(k, static_cast<Eigen::Index>(j));
      csv.row(row.data(), row.size());
    }
    close_output_file(out, dir / "green_time.csv");
  }
  std::ostringstream gp;
  gp << "# Drawn by rollnoise greens from green_time.csv; run `gnuplot green_time.gp` to redraw.\n"
     << "set terminal pngcairo size 1000,500 noenhanced font 'DejaVu Sans,10'\n"
     << "set output 'green_time.png'\nset datafile separator ','\nset grid\nset key top right\n"
     << "set title 'Green function of the " << response.model() << ": unit impulse at point 1'\n"
     << "set xlabel 'time (ms)'\nset ylabel 'g (mm/(N s))'\n"
     << "plot for [c=2:" << points.size() + 1 << "] 'green_time.csv' using ($1*1e3):(column(c)*1e3) with lines lw 1.5 "
        "title columnheader(c)\n";
  write_plot(dir, "green_time", gp.str());
}

}  // namespace

GreensRun run_greens(const GreensRunOptions& options, const fs::path& out) {
  const auto started = std::chrono::steady_clock::now();
  const fs::path input(options.model);
  if (!options.toml) require_regular_file(options.model);
  const CaseFile file = options.toml ? CaseFile::model_from_table(input, *options.toml) : CaseFile::load_model(input);
  const ConfigTable top = file.top();
  // The same cache folder as simulate's (two-layer tables, mode fits).
  const std::optional<fs::path>& cache = options.cache;
  // Kept within its limit before the model's tables and fits may add to it (core/cache_limit.hpp).
  if (cache) keep_cache_within(*cache, options.cache_limit.value_or(kDefaultCacheLimitBytes));
  GreensRun run;
  run.response = make_centre_line_response(top, cache);
  const std::unique_ptr<CentreLineResponse>& response = run.response;
  run.distances = checked_distances(options, *response);
  const std::vector<double>& distances = run.distances;
  const double top_hz = response->default_top_frequency_hz();
  run.frequencies = options.frequencies.empty() ? evenly_spaced(0.0, top_hz, 501) : checked_frequencies(options.frequencies);
  const std::vector<double>& frequencies = run.frequencies;
  // Up to 1e5 frequencies × 1e4 distances: tens of GB in memory, hundreds on disk.
  check_run_fits(estimate_greens_run(frequencies.size(), distances.size()), available_memory_bytes(),
                 available_disk_bytes(out.empty() ? fs::path(".") : out), options.force);

  const auto nf = static_cast<Eigen::Index>(frequencies.size());
  const auto nd = static_cast<Eigen::Index>(distances.size());
  run.receptance.resize(nf, nd);
  run.mobility.resize(nf, nd);
  Eigen::MatrixXcd& receptance = run.receptance;
  Eigen::MatrixXcd& mobility = run.mobility;
  const CancellationToken cancel;  // Ctrl-C (core/cancellation.hpp)
  for (Eigen::Index i = 0; i < nf; ++i) {
    cancel.throw_if_cancelled();
    const double omega = 2.0 * std::numbers::pi * frequencies[static_cast<std::size_t>(i)];
    for (Eigen::Index j = 0; j < nd; ++j) {
      receptance(i, j) = response->receptance(distances[static_cast<std::size_t>(j)], omega);
      mobility(i, j) = std::complex<double>(0.0, omega) * receptance(i, j);  // Y = iω·α
    }
  }
  // The static compliance per distance: the table's 0 Hz row when it has one.
  std::vector<double> static_compliance(distances.size());
  for (std::size_t j = 0; j < distances.size(); ++j)
    static_compliance[j] = frequencies.front() == 0.0 ? receptance(0, static_cast<Eigen::Index>(j)).real()
                                                      : response->receptance(distances[j], 0.0).real();
  if (!receptance.allFinite())
    throw InputError(options.model, "", "the model's receptance is not finite at these frequencies; check its values");

  // The Green's function in time: along the whole circumference for a tyre (512 points, one
  // revolution, as the paper's Fig. 5a), at the model's points otherwise; 200 samples of
  // 1/(2·top frequency).
  const bool tyre = response->circumference() > 0.0;
  std::vector<double>& around = run.around;
  if (tyre) {
    for (int i = 0; i < 512; ++i) around.push_back(-0.5 * response->circumference() + response->circumference() * i / 512.0);
  } else {
    around = response->default_distances();
  }
  const double dt = 0.5 / top_hz;
  constexpr int kTimeSamples = 200;
  run.time.resize(kTimeSamples);
  Eigen::VectorXd& time = run.time;
  for (Eigen::Index k = 0; k < time.size(); ++k) time(k) = static_cast<double>(k + 1) * dt;
  run.green = response->green_table(around, dt, kTimeSamples);

  // A model computed from parameters hands over its modal table, so that a `tabulated` model
  // file can name it. Sampled where the tabulated model's pole fit wants it (0 Hz, then
  // log-spaced 1 Hz – 20 kHz), not on --frequencies: a linear grid to 5 kHz misses the narrow
  // low resonances and the tail the step means need. Through the cache `simulate` shares.
  run.modal_table = response->modal_table(tyre_mode_fit_frequencies(), cache);
  std::optional<ModalReceptanceTable>& modal_table = run.modal_table;
  // The cache names a table it found by its file; a table computed afresh by the model.
  const bool modal_table_from_cache = modal_table && modal_table->source != response->model();
  if (modal_table) modal_table->source = response->model();

  nlohmann::json& summary = run.summary;
  summary["model_file"] = options.model;
  summary["paths_outside_case_folder"] = file.paths_outside_folder();  // via ".." or a symlink
  summary["model"] = response->model();
  summary["description"] = response->description();
  summary["circumference_m"] = response->circumference();
  summary["static_compliance_m_per_N"] = nlohmann::json::array();
  for (std::size_t j = 0; j < distances.size(); ++j)
    summary["static_compliance_m_per_N"].push_back({{"distance_m", distances[j]}, {"value", static_compliance[j]}});
  summary["settings"] = {{"frequencies", frequencies.size()},
                         {"frequency_range_hz", {frequencies.front(), frequencies.back()}},
                         {"distances_m", distances},
                         {"time_step_s", dt},
                         {"time_samples", time.size()}};
  if (modal_table) {
    summary["modal_table"] = {
        {"file", "modal_receptance.h5"},
        {"layout", std::string(modal_table_layout)},
        {"frequencies", modal_table->frequency.size()},
        {"frequency_range_hz", {modal_table->frequency(0), modal_table->frequency(modal_table->frequency.size() - 1)}},
        {"orders", modal_table->orders},
        {"lateral_orders", modal_table->lateral_orders},
        {"first_lateral_order", modal_table->first_lateral_order},
        {"lateral_shape", modal_table->lateral_shape == LateralShape::sine ? "sine" : "cosine"},
        {"from_cache", modal_table_from_cache},
        {"use", "a model file with model = \"tabulated\" and file = \"<path to modal_receptance.h5>\""}};
  }
  if (const FittedModalTyre* fitted = response->fitted_modes()) {
    const ModalReceptanceTable& table = fitted->table();
    const ModalFitReport& fit = fitted->fit_report();
    summary["table"] = {{"file", table.source},
                        {"frequencies", table.frequency.size()},
                        {"frequency_range_hz", {table.frequency(0), table.frequency(table.frequency.size() - 1)}},
                        {"orders", table.orders},
                        {"lateral_orders", table.lateral_orders},
                        {"first_lateral_order", table.first_lateral_order},
                        {"lateral_shape", table.lateral_shape == LateralShape::sine ? "sine" : "cosine"}};
    summary["mode_fit"] = {{"modes", fit.modes},
                           {"poles", fit.poles},
                           {"unconverged_modes", fit.unconverged},
                           {"worst_rms_error", fit.worst_rms_error},
                           {"mean_rms_error", fit.mean_rms_error},
                           {"worst_max_error", fit.worst_max_error},
                           {"worst_mode", {fit.worst_order, fit.worst_lateral_order}},
                           {"fit_time_s", fit.seconds}};
  }
  summary["rollnoise_version"] = ROLLNOISE_VERSION;
  summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return run;
}

void write_greens_outputs(const fs::path& out, const GreensRun& run) {
  StagedOutputDirectory staged(out);
  const std::vector<double>& frequencies = run.frequencies;
  const std::vector<double>& distances = run.distances;
  const CentreLineResponse* response = run.response.get();
  const std::optional<ModalReceptanceTable>& modal_table = run.modal_table;
  write_table(staged.staging() / "receptance.csv", frequencies, distances, run.receptance);
  write_table(staged.staging() / "mobility.csv", frequencies, distances, run.mobility);
  {
    Hdf5Writer h5(staged.staging() / "greens.h5");
    h5.attribute("/", "model", response->model());
    h5.attribute("/", "description", response->description());
    h5.attribute("/", "circumference_m", response->circumference());
    h5.attribute("/", "rollnoise_version", std::string(ROLLNOISE_VERSION));
    h5.group("frequency_domain");
    const Eigen::Map<const Eigen::VectorXd> f(frequencies.data(), static_cast<Eigen::Index>(frequencies.size()));
    const Eigen::Map<const Eigen::VectorXd> d(distances.data(), static_cast<Eigen::Index>(distances.size()));
    h5.write("frequency_domain/frequency", Eigen::VectorXd(f), "Hz", "frequencies of the rows");
    h5.write("frequency_domain/distance", Eigen::VectorXd(d), "m",
             "response points along the circumference on the centre line from the excitation (columns)");
    h5.write("frequency_domain/receptance_re", Eigen::MatrixXd(run.receptance.real()), "m/N",
             "real part of the receptance u/F, [frequency][distance]; 0 Hz: the static compliance");
    h5.write("frequency_domain/receptance_im", Eigen::MatrixXd(run.receptance.imag()), "m/N",
             "imaginary part of the receptance u/F, [frequency][distance]");
    h5.group("time_domain");
    h5.write("time_domain/time", run.time, "s", "times after the impulse (rows)");
    h5.write("time_domain/distance", Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(run.around.data(),
                                                                                         static_cast<Eigen::Index>(run.around.size()))),
             "m", "response points (columns): one revolution for a tyre, the points of a point model");
    h5.write("time_domain/green", run.green, "m/(N*s)",
             "displacement per unit impulse at x = 0, [time][distance], without the instantaneous (delta) part");
  }
  if (modal_table) {
    write_modal_table(staged.staging() / "modal_receptance.h5", *modal_table);
    plot_dispersion(staged.staging(), *modal_table);
  }
  if (response->circumference() > 0.0) {
    write_greens_circumference(staged.staging(), *response, 512);
  } else {
    write_green_against_time(staged.staging(), *response, run.time, run.green, run.around);
  }
  plot_mobility(staged.staging(), *response, distances, frequencies.front() > 0.0);

  write_text_file(staged.staging() / "summary.json", run.summary.dump(2) + "\n");
  staged.commit();
}

}  // namespace rollnoise
