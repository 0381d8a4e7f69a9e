#include "study/study_results.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string_view>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/csv.hpp"
#include "core/gnuplot.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

// Pieces joined (GCC 12 warns falsely, -Wrestrict, on chains of string + string).
std::string join(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) out += p;
  return out;
}

// Replaces `path` by `text` in one rename, so a reader never sees half a file.
void replace_file(const fs::path& path, const std::string& text) {
  const fs::path temporary = path.parent_path() / join({".", path.filename().string(), ".tmp-", std::to_string(::getpid())});
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  fs::rename(temporary, path);
}

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A CSV cell: quoted when it holds a comma or a quote.
std::string cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  out += '"';
  return out;
}

std::string gnuplot_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  out += '\'';
  return out;
}

struct CaseData {
  bool ok = false;
  nlohmann::json summary;
  // receiver → (band label, LpA) in the order of spectrum.csv
  std::map<std::string, std::vector<std::pair<std::string, double>>> spectra;
  std::vector<std::string> spectrum_lines;  // receiver,band_hz,Lp_dB,LpA_dB as the case wrote them
};

CaseData read_case(const fs::path& folder) {
  CaseData d;
  d.summary = nlohmann::json::parse(read_all(folder / "summary.json"));
  d.ok = true;
  std::istringstream spectrum(read_all(folder / "spectrum.csv"));
  std::string line;
  std::getline(spectrum, line);  // header
  while (std::getline(spectrum, line)) {
    if (line.empty()) continue;
    d.spectrum_lines.push_back(line);
    std::vector<std::string> parts;
    std::istringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) parts.push_back(f);
    if (parts.size() == 4) d.spectra[parts[0]].emplace_back(parts[1], std::stod(parts[3]));
  }
  return d;
}

// Least-squares L = a + b·x.
std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double b = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return {(sy - b * sx) / n, b};
}

std::string safe(const std::string& text) {
  std::string out;
  for (char c : text) out += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ? c : '_';
  return out;
}

}  // namespace

nlohmann::json write_study_results(const fs::path& out, const StudySpec& spec, const std::vector<StudyCase>& cases,
                                   const std::vector<CaseOutcome>& outcomes, const nlohmann::json& run, bool plots) {
  std::vector<CaseData> data(cases.size());
  std::vector<std::string> receivers;  // in the order of the first case that has them
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (outcomes[i].status != "ok") continue;
    data[i] = read_case(case_folder(out, cases[i]));
    if (data[i].summary.contains("levels"))
      for (const auto& [name, value] : data[i].summary["levels"].items())
        if (std::find(receivers.begin(), receivers.end(), name) == receivers.end()) receivers.push_back(name);
  }

  // results.csv
  std::ostringstream results;
  for (const StudyParameter& p : spec.varied) results << cell(p.key.dotted()) << ',';
  for (const std::string& r : receivers) results << cell(join({"LAeq_", r, "_dB"})) << ',';
  results << "LWA_dB,rolling_resistance_N,wall_time_s,status\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    for (const std::string& label : cases[i].labels) results << cell(label) << ',';
    const nlohmann::json& s = data[i].summary;
    const auto number = [&](const nlohmann::json::json_pointer& at) {
      return data[i].ok && s.contains(at) ? format_number(s[at].get<double>()) : std::string();
    };
    for (const std::string& r : receivers) results << number(nlohmann::json::json_pointer(join({"/levels/", r, "/LAeq_dB"}))) << ',';
    results << number(nlohmann::json::json_pointer("/sound_power/LwA_dB")) << ','
            << number(nlohmann::json::json_pointer("/rolling_resistance_N")) << ','
            << (data[i].ok ? number(nlohmann::json::json_pointer("/wall_time_s")) : format_number(outcomes[i].wall_time_s))
            << ',' << outcomes[i].status << '\n';
  }
  replace_file(out / "results.csv", results.str());

  // spectra.csv, long form
  std::ostringstream spectra;
  for (const StudyParameter& p : spec.varied) spectra << cell(p.key.dotted()) << ',';
  spectra << "receiver,band_hz,Lp_dB,LpA_dB\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::string keys;
    for (const std::string& label : cases[i].labels) {
      keys += cell(label);
      keys += ',';
    }
    for (const std::string& line : data[i].spectrum_lines) spectra << keys << line << '\n';
  }
  replace_file(out / "spectra.csv", spectra.str());

  // The plots' axes: speed, and the series (the other varied keys).
  std::optional<std::size_t> speed_key, surface_key;
  for (std::size_t k = 0; k < spec.varied.size(); ++k) {
    if (spec.varied[k].key.dotted() == "rolling.speed") speed_key = k;
    if (spec.varied[k].key.dotted() == "road.surface") surface_key = k;
  }
  const auto series_of = [&](const StudyCase& c, std::optional<std::size_t> leave_out) {
    std::string label;
    for (std::size_t k = 0; k < c.labels.size(); ++k)
      if (k != speed_key && k != leave_out) label += join({label.empty() ? "" : ", ", c.labels[k]});
    return label.empty() ? std::string("all") : label;
  };
  const auto speed_of = [&](const StudyCase& c) {
    return speed_key ? spec.varied[*speed_key].values.get(c.choice[*speed_key])->value<double>().value_or(0.0) : 0.0;
  };
  std::vector<std::string> series;
  std::map<std::string, std::vector<std::size_t>> by_series;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string s = series_of(cases[i], std::nullopt);
    if (!by_series.count(s)) series.push_back(s);
    by_series[s].push_back(i);
  }

  nlohmann::json fits = nlohmann::json::array();
  if (speed_key && spec.varied[*speed_key].values.size() >= 2) {
    // The axis spans the study's speeds (km/h), with a tic at each.
    double slowest = 0.0, fastest = 0.0;
    std::string speed_tics;
    const StudyParameter& speeds = spec.varied[*speed_key];
    for (std::size_t v = 0; v < speeds.values.size(); ++v) {
      const double kmh = 3.6 * speeds.values.get(v)->value<double>().value_or(0.0);
      slowest = v ? std::min(slowest, kmh) : kmh;
      fastest = v ? std::max(fastest, kmh) : kmh;
      if (v) speed_tics += ", ";
      speed_tics += format_number(std::round(kmh * 10.0) / 10.0);
    }
    for (const std::string& r : receivers) {
      std::ostringstream dat, gp;
      const std::string name = join({"level_speed_", safe(r)});
      gp << "# Drawn by rollnoise from " << name << ".dat (one block per series: speed km/h, LAeq dB);\n"
         << "# run `gnuplot " << name << ".gp` to redraw. Lines: L = a + b lg(v/" << kReferenceSpeedKmh << " km/h).\n"
         << "set terminal pngcairo size 1000,600 noenhanced font 'DejaVu Sans,10'\nset output '" << name << ".png'\n"
         << "set grid\nset logscale x\nset key outside right\nset xlabel 'speed (km/h)'\n"
         << "set ylabel " << gnuplot_quoted(join({"LAeq at ", r, " (dB)"})) << "\n"
         << "set xrange [" << format_number(slowest / 1.1) << ":" << format_number(fastest * 1.1) << "]\nset xtics ("
         << speed_tics << ")\n"
         << "set title " << gnuplot_quoted(join({"Study ", spec.name, ": level against speed"})) << "\nplot ";
      int block = 0;
      for (const std::string& s : series) {
        std::vector<double> x, y;
        for (std::size_t i : by_series[s]) {
          const nlohmann::json::json_pointer at(join({"/levels/", r, "/LAeq_dB"}));
          if (!data[i].ok || !data[i].summary.contains(at)) continue;
          const double kmh = speed_of(cases[i]) * 3.6;
          x.push_back(std::log10(kmh / kReferenceSpeedKmh));
          y.push_back(data[i].summary[at].get<double>());
          dat << format_number(kmh) << ' ' << format_number(y.back()) << '\n';
        }
        dat << "\n\n";
        if (x.size() < 2) {
          ++block;
          continue;
        }
        const auto [a, b] = fit_line(x, y);
        fits.push_back({{"series", s}, {"receiver", r}, {"a_dB", a}, {"b_dB_per_decade", b}, {"v0_kmh", kReferenceSpeedKmh}});
        std::ostringstream legend;
        legend.precision(3);
        legend << s << ": b = " << b;
        gp << (block ? ", \\\n     " : "") << "'" << name << ".dat' index " << block << " using 1:2 with points pt 7 lc "
           << block + 1 << " notitle, " << format_number(a) << " + " << format_number(b) << "*log10(x/"
           << kReferenceSpeedKmh << ") with lines lw 1.5 lc " << block + 1 << " title " << gnuplot_quoted(legend.str());
        ++block;
      }
      gp << '\n';
      if (plots && !fits.empty()) {
        replace_file(out / join({name, ".dat"}), dat.str());
        write_plot(out, name, gp.str());
      }
    }
  }

  // Spectra per series at each speed (the first receiver, A-weighted).
  if (plots && !receivers.empty()) {
    const std::string& r = receivers.front();
    std::map<std::string, std::vector<std::size_t>> by_speed;  // speed label → cases
    std::vector<std::string> speeds;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const std::string v = speed_key ? cases[i].labels[*speed_key] : std::string("all");
      if (!by_speed.count(v)) speeds.push_back(v);
      by_speed[v].push_back(i);
    }
    for (const std::string& v : speeds) {
      const std::string name = speed_key ? join({"spectra_speed_", safe(v)}) : std::string("spectra");
      std::ostringstream dat, gp;
      gp << "# Drawn by rollnoise from " << name << ".dat (one block per case: band Hz, LpA dB).\n"
         << "set terminal pngcairo size 1000,600 noenhanced font 'DejaVu Sans,10'\nset output '" << name << ".png'\n"
         << "set grid\nset logscale x\nset key outside right\nset xlabel 'third-octave band (Hz)'\n"
         << "set ylabel " << gnuplot_quoted(join({"LpA at ", r, " (dB)"})) << "\nset title "
         << gnuplot_quoted(join({"Study ", spec.name, speed_key ? join({": spectra at ", v, " m/s"}) : std::string(": spectra")})) << "\nplot ";
      int block = 0;
      for (std::size_t i : by_speed[v]) {
        if (!data[i].ok || !data[i].spectra.count(r)) continue;
        for (const auto& [band, lpa] : data[i].spectra.at(r)) dat << band << ' ' << format_number(lpa) << '\n';
        dat << "\n\n";
        gp << (block ? ", \\\n     " : "") << "'" << name << ".dat' index " << block
           << " using 1:2 with linespoints lw 1.5 pt 7 ps 0.5 title " << gnuplot_quoted(series_of(cases[i], std::nullopt));
        ++block;
      }
      gp << '\n';
      if (block) {
        replace_file(out / join({name, ".dat"}), dat.str());
        write_plot(out, name, gp.str());
      }
    }
    // Each surface's difference to the reference, per band, at each speed (and other keys).
    if (surface_key && !spec.reference_surface.empty()) {
      const StudyParameter& surfaces = spec.varied[*surface_key];
      std::size_t reference = 0;
      for (std::size_t s = 0; s < surfaces.values.size(); ++s)
        if (surfaces.values.get(s)->value<std::string>() == spec.reference_surface) reference = s;
      std::ostringstream dat, gp;
      const std::string name = "difference_to_reference";
      gp << "# Drawn by rollnoise from " << name << ".dat (one block per case: band Hz, LpA - LpA of the reference, dB).\n"
         << "set terminal pngcairo size 1000,600 noenhanced font 'DejaVu Sans,10'\nset output '" << name << ".png'\n"
         << "set grid\nset logscale x\nset key outside right\nset xlabel 'third-octave band (Hz)'\n"
         << "set ylabel " << gnuplot_quoted(join({"LpA - LpA on ", surfaces.labels[reference], " at ", r, " (dB)"}))
         << "\nset title " << gnuplot_quoted(join({"Study ", spec.name, ": difference to the reference surface"})) << "\nplot ";
      int block = 0;
      for (std::size_t i = 0; i < cases.size(); ++i) {
        if (cases[i].choice[*surface_key] == reference || !data[i].ok || !data[i].spectra.count(r)) continue;
        // The case on the reference surface with every other value the same.
        std::size_t match = i;
        for (std::size_t j = 0; j < cases.size(); ++j) {
          bool same = cases[j].choice[*surface_key] == reference;
          for (std::size_t k = 0; same && k < cases[j].choice.size(); ++k)
            same = k == *surface_key || cases[j].choice[k] == cases[i].choice[k];
          if (same) match = j;
        }
        if (match == i || !data[match].ok || !data[match].spectra.count(r)) continue;
        std::map<std::string, double> ref(data[match].spectra.at(r).begin(), data[match].spectra.at(r).end());
        for (const auto& [band, lpa] : data[i].spectra.at(r))
          if (ref.count(band)) dat << band << ' ' << format_number(lpa - ref[band]) << '\n';
        dat << "\n\n";
        std::string label;
        for (std::size_t k = 0; k < cases[i].labels.size(); ++k) label += join({k ? ", " : "", cases[i].labels[k]});
        gp << (block ? ", \\\n     " : "") << "'" << name << ".dat' index " << block
           << " using 1:2 with linespoints lw 1.5 pt 7 ps 0.5 title " << gnuplot_quoted(label);
        ++block;
      }
      gp << '\n';
      if (block) {
        replace_file(out / join({name, ".dat"}), dat.str());
        write_plot(out, name, gp.str());
      }
    }
  }

  nlohmann::json summary = run;
  summary["study"] = spec.name;
  summary["study_file"] = spec.file.string();
  summary["base_case"] = spec.base_case.string();
  if (!spec.reference_surface.empty()) summary["reference_surface"] = spec.reference_surface;
  std::size_t ok = 0, failed = 0, reused = 0;
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t i = 0; i < cases.size(); ++i) {
    ok += outcomes[i].status == "ok";
    failed += outcomes[i].status == "failed";
    reused += outcomes[i].reused;
    nlohmann::json values = nlohmann::json::object();
    for (std::size_t k = 0; k < spec.varied.size(); ++k) values[spec.varied[k].key.dotted()] = cases[i].labels[k];
    nlohmann::json entry = {{"id", cases[i].id}, {"values", values}, {"status", outcomes[i].status}};
    if (!outcomes[i].message.empty()) entry["message"] = outcomes[i].message;
    if (outcomes[i].reused) entry["from_earlier_run"] = true;
    list.push_back(entry);
  }
  summary["cases"] = {{"total", cases.size()}, {"ok", ok}, {"failed", failed}, {"from_earlier_run", reused}};
  summary["case_list"] = list;
  summary["level_fits"] = fits;
  replace_file(out / "summary.json", summary.dump(2) + "\n");
  return summary;
}

}  // namespace rollnoise
