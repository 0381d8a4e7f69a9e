#include "simulation/calibration_run.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include "calibrate/calibrated_model_file.hpp"
#include "calibrate/calibration_model_factory.hpp"
#include "calibrate/frf_csv_reader.hpp"
#include "calibrate/frf_uff_reader.hpp"
#include "core/case_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/gnuplot.hpp"
#include "core/output_directory.hpp"
#include "core/progress.hpp"
#include "simulation/run_size.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

namespace {

std::optional<double> parse_number(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

// "X,Y" in m.
BeltPosition parse_position(const std::string& text, const std::string& option) {
  const auto comma = text.find(',');
  const auto x = comma == std::string::npos ? std::nullopt : parse_number(std::string_view(text).substr(0, comma));
  const auto y = comma == std::string::npos ? std::nullopt : parse_number(std::string_view(text).substr(comma + 1));
  if (!x || !y)
    throw InputError(option, text,
                     "expected X,Y in m (x along the circumference, y across the belt from one edge), such as "
                     "0.1,0.09");
  return {*x, *y};
}

std::map<std::int64_t, BeltPosition> parse_nodes(const std::vector<std::string>& nodes) {
  std::map<std::int64_t, BeltPosition> out;
  for (const std::string& item : nodes) {
    const auto eq = item.find('=');
    std::int64_t node = 0;
    const auto [ptr, ec] = std::from_chars(item.data(), item.data() + (eq == std::string::npos ? 0 : eq), node);
    if (eq == std::string::npos || eq == 0 || ec != std::errc() || ptr != item.data() + eq)
      throw InputError("--node", item, "expected N=X,Y: a UFF node number and its position in m, such as 2=0.1,0.09");
    if (out.count(node)) throw InputError("--node", item, "node " + std::to_string(node) + " is given twice");
    out[node] = parse_position(item.substr(eq + 1), "--node");
  }
  return out;
}

bool looks_like_uff(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".uff" || ext == ".unv") return true;
  if (ext == ".csv" || ext == ".txt") return false;
  // Anything else: a UFF file opens with a line holding "-1".
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    return line.compare(first, 2, "-1") == 0;
  }
  return false;
}

// Reads every data file; positions from the files, then --node, --response, --excitation.
std::vector<MeasuredFrf> read_data(const CalibrationRunOptions& options, std::vector<std::string>& notes) {
  const std::optional<FrfQuantity> quantity = parse_frf_quantity(options.data_type);
  if (!quantity)
    throw InputError("--data-type", options.data_type, "must be mobility, receptance or accelerance");
  const FrfReadOptions read{*quantity, options.data_type_given};
  const std::map<std::int64_t, BeltPosition> nodes = parse_nodes(options.nodes);
  const std::size_t files = options.data.size();
  for (const auto* list : {&options.response, &options.excitation}) {
    if (list->size() > 1 && list->size() != files) {
      std::ostringstream problem;
      problem << "is given " << list->size() << " times for " << files
              << " data files: give it once (for every FRF without a position of its own) or once per data file, in "
                 "the order of --data";
      throw InputError(list == &options.response ? "--response" : "--excitation", "", problem.str());
    }
  }
  std::vector<MeasuredFrf> all;
  for (std::size_t i = 0; i < files; ++i) {
    const fs::path path(options.data[i]);
    FrfFile file = looks_like_uff(path) ? read_uff_frfs(path, read) : read_frf_csv(path, read);
    notes.insert(notes.end(), file.notes.begin(), file.notes.end());
    for (MeasuredFrf& frf : file.frfs) {
      // UFF nodes with a position.
      if (frf.response_dof && frf.reference_dof && !nodes.empty()) {
        const auto r = nodes.find(frf.response_dof->node);
        const auto e = nodes.find(frf.reference_dof->node);
        if (r == nodes.end() || e == nodes.end()) {
          const std::int64_t missing = r == nodes.end() ? frf.response_dof->node : frf.reference_dof->node;
          throw InputError(frf.source, frf.label,
                           "node " + std::to_string(missing) + " has no position: give --node " +
                               std::to_string(missing) + "=X,Y");
        }
        frf.response = r->second;
        frf.excitation = e->second;
      }
      // --response/--excitation once per file overrides; once in all fills in.
      const auto apply = [&](const std::vector<std::string>& list, std::optional<BeltPosition>& target,
                             const char* option) {
        if (list.size() == files && files > 1)
          target = parse_position(list[i], option);
        else if (list.size() == 1 && (files == 1 || !target))
          target = parse_position(list[0], option);
      };
      apply(options.response, frf.response, "--response");
      apply(options.excitation, frf.excitation, "--excitation");
      all.push_back(std::move(frf));
    }
  }
  return all;
}

void parse_frequency_range(const std::string& text, CalibrationSettings& settings) {
  if (text.empty()) return;
  const auto colon = text.find(':');
  const auto lo = colon == std::string::npos ? std::nullopt : parse_number(std::string_view(text).substr(0, colon));
  const auto hi = colon == std::string::npos ? std::nullopt : parse_number(std::string_view(text).substr(colon + 1));
  if (!lo || !hi || !(*lo >= 0.0) || !(*hi > *lo))
    throw InputError("--frequency-range", text, "expected LO:HI in Hz with 0 <= LO < HI, such as 20:2000");
  settings.min_frequency_hz = *lo;
  settings.max_frequency_hz = *hi;
}

double degrees(std::complex<double> z) { return std::arg(z) * 180.0 / std::numbers::pi; }

void write_fit_csv(const fs::path& path, const CalibrationResult& result) {
  std::ofstream out(path, std::ios::binary);
  CsvWriter csv(out, {"frf", "frequency_hz", "measured_re", "measured_im", "fitted_re", "fitted_im",
                      "measured_magnitude", "measured_phase_deg", "fitted_magnitude", "fitted_phase_deg", "weight"});
  for (std::size_t f = 0; f < result.frfs.size(); ++f) {
    const FittedFrf& frf = result.frfs[f];
    for (Eigen::Index k = 0; k < frf.frequency_hz.size(); ++k) {
      const std::complex<double> m = frf.measured[k];
      const std::complex<double> y = frf.fitted[k];
      const double row[] = {static_cast<double>(f + 1), frf.frequency_hz[k], m.real(), m.imag(), y.real(), y.imag(),
                            std::abs(m), degrees(m), std::abs(y), degrees(y), frf.weight[k]};
      csv.row(row, std::size(row));
    }
  }
  close_output_file(out, path);
}

std::string gnuplot_text(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '\'' ? '"' : c;
  return out;
}

void plot_fit(const fs::path& dir, const CalibrationResult& result) {
  std::ostringstream gp;
  gp << "# Drawn by rollnoise calibrate from fit.csv; run `gnuplot fit.gp` to redraw.\n"
     << "set terminal pngcairo size 1000,850 noenhanced font 'DejaVu Sans,10'\n"
     << "set output 'fit.png'\nset datafile separator ','\nset grid\nset logscale x\nset autoscale xfix\nset key outside right\n"
     << "set multiplot layout 2,1 title 'rollnoise calibrate: measured (points) and fitted (lines) mobility'\n"
     << "set logscale y\nset ylabel '|Y| (m/(N s))'\nset format y '%.0e'\n";
  const auto plots = [&](int measured_column, int fitted_column) {
    gp << "plot ";
    for (std::size_t f = 0; f < result.frfs.size(); ++f) {
      const int index = static_cast<int>(f) + 1;
      const std::string name = gnuplot_text(fs::path(result.frfs[f].name).filename().string());
      gp << (f ? ", \\\n     " : "") << "'fit.csv' skip 1 using (($1 == " << index << ") ? $2 : 1/0):"
         << measured_column << " with points pt 7 ps 0.4 lc " << index << " title '" << index << ": " << name
         << "', \\\n     'fit.csv' skip 1 using (($1 == " << index << ") ? $2 : 1/0):" << fitted_column
         << " with lines lw 2 lc " << index << " notitle";
    }
    gp << "\n";
  };
  plots(7, 9);
  gp << "unset logscale y\nset format y '%g'\nset ylabel 'phase (deg)'\nset yrange [-180:180]\nset ytics 90\n"
     << "set xlabel 'frequency (Hz)'\n";
  plots(8, 10);
  gp << "unset multiplot\n";
  write_plot(dir, "fit", gp.str());
}

nlohmann::json position_json(const BeltPosition& p) { return nlohmann::json::array({p.x, p.y}); }

nlohmann::json number_or_null(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

nlohmann::json report_json(const CalibrationRunOptions& options, const CalibrationModel& model,
                           const CalibrationSettings& settings, const std::vector<MeasuredFrf>& data,
                           const CalibrationResult& result, double wall_time) {
  nlohmann::json report;
  report["model_file"] = options.model;
  report["model"] = result.model;
  nlohmann::json parameters = nlohmann::json::object();
  for (const FittedParameter& p : result.fitted) {
    parameters[p.name] = {{"value", p.value},
                          {"std_error", p.std_error},
                          {"relative_std_error", p.log_scale ? nlohmann::json(p.log_std_error) : nlohmann::json()},
                          {"initial", p.initial},
                          {"lower", p.lower},
                          {"upper", p.upper},
                          {"unit", p.unit},
                          {"log_space", p.log_scale},
                          {"at_bound", p.at_bound}};
  }
  report["parameters"] = parameters;
  nlohmann::json fixed = nlohmann::json::object();
  for (std::size_t k = 0; k < result.parameter_names.size(); ++k) {
    const bool free = std::any_of(result.fitted.begin(), result.fitted.end(),
                                  [&](const FittedParameter& p) { return p.name == result.parameter_names[k]; });
    if (!free) fixed[result.parameter_names[k]] = result.values[k];
  }
  report["fixed_parameters"] = fixed;
  report["transducer_mass_kg"] = result.transducer_mass;
  report["cost"] = result.cost;
  report["iterations"] = result.iterations;
  nlohmann::json names = nlohmann::json::array();
  for (const FittedParameter& p : result.fitted) names.push_back(p.name);
  nlohmann::json matrix = nlohmann::json::array();
  for (Eigen::Index i = 0; i < result.correlation.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < result.correlation.cols(); ++j) row.push_back(number_or_null(result.correlation(i, j)));
    matrix.push_back(row);
  }
  report["correlations"] = {{"parameters", names}, {"matrix", matrix}};
  report["covariance_full_rank"] = result.full_rank;
  {
    const Eigen::VectorXd& s = result.singular_values;
    nlohmann::json values = nlohmann::json::array();
    for (Eigen::Index i = 0; i < s.size(); ++i) values.push_back(s[i]);
    report["conditioning"] = {
        {"singular_values", values},
        {"condition_number", s.size() > 0 && s[s.size() - 1] > 0.0 ? nlohmann::json(s[0] / s[s.size() - 1])
                                                                   : nlohmann::json()},
        {"about", "singular values of the weighted Jacobian at the optimum, per unit of the unknowns (log p)"}};
  }
  report["warnings"] = result.warnings;
  report["residual"] = {{"sigma", result.residual_sigma},
                        {"rms_log_magnitude", result.rms_log_magnitude},
                        {"rms_magnitude_dB", 20.0 / std::log(10.0) * result.rms_log_magnitude},
                        {"rms_phase_deg", result.rms_phase * 180.0 / std::numbers::pi},
                        {"lines", result.lines}};
  report["fit_band_hz"] = {result.fit_min_hz, number_or_null(result.fit_max_hz)};
  nlohmann::json starts = nlohmann::json::array();
  for (const StartOutcome& s : result.starts)
    starts.push_back({{"cost", number_or_null(s.cost)}, {"iterations", s.iterations}, {"termination", s.termination}});
  report["best_start"] = result.best_start + 1;
  report["starts"] = starts;
  nlohmann::json frfs = nlohmann::json::array();
  for (std::size_t f = 0; f < result.frfs.size(); ++f) {
    const FittedFrf& fit = result.frfs[f];
    const MeasuredFrf& measured = data[f];
    nlohmann::json entry = {{"index", f + 1},
                            {"name", fit.name},
                            {"quantity", frf_quantity_name(measured.quantity)},
                            {"lines_fitted", fit.frequency_hz.size()},
                            {"lines_left_out", fit.left_out},
                            {"response", position_json(fit.points.response)},
                            {"excitation", position_json(fit.points.excitation)}};
    if (measured.response_dof)
      entry["response_dof"] = {{"node", measured.response_dof->node}, {"direction", measured.response_dof->direction}};
    if (measured.reference_dof)
      entry["reference_dof"] = {{"node", measured.reference_dof->node},
                                {"direction", measured.reference_dof->direction}};
    frfs.push_back(entry);
  }
  report["data"] = frfs;
  nlohmann::json free = nlohmann::json::array();
  for (const FittedParameter& p : result.fitted) free.push_back(p.name);
  report["settings"] = {{"fit", free},
                        {"starts", settings.starts},
                        {"seed", settings.seed},
                        {"loss", "cauchy"},
                        {"loss_scale", settings.loss_scale},
                        {"weighting", "each third-octave band of each FRF weighs the same"},
                        {"model_valid_up_to_hz", number_or_null(model.highest_frequency_hz())},
                        {"stage_tops_hz", result.stage_tops_hz}};
  report["rollnoise_version"] = ROLLNOISE_VERSION;
  report["wall_time_s"] = wall_time;
  return report;
}

std::vector<std::string> calibrated_header(const CalibrationRunOptions& options, const CalibrationResult& result) {
  std::vector<std::string> lines = {"Calibrated by `rollnoise calibrate` (rollnoise " ROLLNOISE_VERSION ") from " +
                                        options.model + " against:"};
  for (const std::string& d : options.data) lines.push_back("  " + d);
  lines.push_back("Fitted values (standard errors from the covariance at the optimum; see report.json):");
  for (const FittedParameter& p : result.fitted) {
    std::ostringstream line;
    line.precision(5);
    line << "  " << p.name << " = " << p.value << " +- " << p.std_error << " " << p.unit << " (file: " << p.initial
         << ")";
    lines.push_back(line.str());
  }
  for (const std::string& w : result.warnings) lines.push_back("warning: " + w);
  lines.push_back("The rest of the file is the original, comments included.");
  lines.push_back("");
  return lines;
}

}  // namespace

CalibrationRun run_calibration(const CalibrationRunOptions& options, const fs::path& out) {
  const auto started = std::chrono::steady_clock::now();
  const CaseFile model_file = CaseFile::load_model(options.model);
  CalibrationSettings settings;
  parse_frequency_range(options.frequency_range, settings);
  // The two-layer tyre chooses the modes it solves exactly for the band's top.
  std::unique_ptr<CalibrationModel> model = make_calibration_model(model_file, settings.max_frequency_hz);

  CalibrationRun run;
  run.data = read_data(options, run.notes);
  if (options.note)
    for (const std::string& note : run.notes) options.note(note);
  const std::vector<MeasuredFrf>& data = run.data;
  // Data that end below the band's top need no modes for above them.
  double data_top = 0.0;
  for (const MeasuredFrf& frf : data)
    if (frf.size() > 0) data_top = std::max(data_top, frf.frequency_hz.maxCoeff());
  if (data_top > settings.min_frequency_hz && data_top < model->highest_frequency_hz())
    model = make_calibration_model(model_file, data_top);
  // The fit's size follows the data (no reader caps it): refused before a long fit whose
  // fit.csv would not fit on the disk. Every line and parameter counted: on the safe side.
  {
    std::uint64_t lines = 0;
    for (const MeasuredFrf& frf : data) lines += static_cast<std::uint64_t>(frf.size());
    const std::string source = options.data.size() == 1 ? options.data.front() : "the --data files";
    check_run_fits(estimate_calibration_run(lines, model->parameters().size() + 1, source), available_memory_bytes(),
                   available_disk_bytes(out.empty() ? fs::path(".") : out), options.force);
  }

  settings.free = options.fit;
  settings.transducer_mass = options.transducer_mass;
  settings.starts = options.starts > 0 ? options.starts : model->default_starts();
  settings.seed = options.seed;
  settings.loss_scale = options.loss_scale;
  settings.first_stage_hz = options.first_stage;
  // Progress by starts; within a start, iteration i counts as i/(i + 10) of it (how many
  // iterations a start takes is not known ahead). ProgressReporter looks at every 256th count.
  constexpr std::size_t steps_per_start = 1000;
  ProgressReporter progress("calibrate " + fs::path(options.model).filename().string(),
                            static_cast<std::size_t>(settings.starts) * steps_per_start * 256, {}, options.progress,
                            options.progress_sink);
  settings.progress = [&progress](int start, int, int iteration) {
    const double within = static_cast<double>(iteration) / (static_cast<double>(iteration) + 10.0);
    const auto step = static_cast<std::size_t>((static_cast<double>(start) + within) * steps_per_start);
    progress.update(step * 256);
  };
  run.result = calibrate(*model, data, settings);
  const CalibrationResult& result = run.result;
  progress.finish();

  std::string original;
  {
    std::ifstream in(options.model, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    original = text.str();
  }
  std::vector<std::pair<std::string, double>> values;
  for (const FittedParameter& p : result.fitted)
    if (p.name != "transducer_mass") values.emplace_back(p.name, p.value);
  run.calibrated = calibrated_model_text(original, options.model, values, calibrated_header(options, result));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  run.report = report_json(options, *model, settings, data, result, wall);
  return run;
}

void write_calibration_outputs(const fs::path& out, const CalibrationRun& run) {
  StagedOutputDirectory staged(out);
  write_text_file(staged.staging() / "calibrated.toml", run.calibrated);
  write_fit_csv(staged.staging() / "fit.csv", run.result);
  plot_fit(staged.staging(), run.result);
  write_text_file(staged.staging() / "report.json", run.report.dump(2) + "\n");
  staged.commit();
}

}  // namespace rollnoise
