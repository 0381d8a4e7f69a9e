#include "simulation/sound_report.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "acoustics/sound_levels.hpp"
#include "core/csv.hpp"
#include "core/output_directory.hpp"
#include "core/error.hpp"
#include "core/gnuplot.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

void plot_spectra(const fs::path& dir, const std::vector<ReceiverSignal>& signals, PlotBatch* batch) {
  std::ostringstream gp;
  gp << "# Drawn by rollnoise from spectrum.csv; run `gnuplot spectrum.gp` to redraw.\n"
     << "set terminal pngcairo size 1000,550 noenhanced font 'DejaVu Sans,10'\n"
     << "set output 'spectrum.png'\nset datafile separator ','\nset grid\nset logscale x\n"
     << "set xlabel 'third-octave band (Hz)'\nset ylabel 'L_pA (dB(A) re 20 uPa)'\nset key outside right\n"
     << "set title 'A-weighted third-octave band levels'\n"
     << "# The 60 dB below the loudest band: the quiet low bands would squash the rest.\n"
     << "stats 'spectrum.csv' skip 1 using 4 nooutput\nset yrange [STATS_max - 60 : STATS_max + 5]\nplot ";
  for (std::size_t i = 0; i < signals.size(); ++i) {
    gp << (i ? ", \\\n     " : "") << "'spectrum.csv' skip 1 using ((strcol(1) eq '" << signals[i].name
       << "') ? $2 : 1/0):4 with linespoints lw 1.5 pt 7 ps 0.6 title '" << signals[i].name << "'";
  }
  gp << "\n";
  write_plot(dir, "spectrum", gp.str(), batch);
}

}  // namespace

SoundReport sound_report(const std::vector<ReceiverSignal>& signals, const std::string& source) {
  SoundReport report;
  report.levels = nlohmann::json::object();
  for (const ReceiverSignal& r : signals) {
    const std::span<const double> p(r.pressure.data(), static_cast<std::size_t>(r.pressure.size()));
    const double duration = static_cast<double>(p.size()) / r.sample_rate;
    BandSpectrumOptions bands;
    // Bands up to 10 kHz, or as far as the band filters meet the IEC 61260-1 class 1 mask
    // (upper band edge below about fs/4); the filters' start-up is left out of the averages
    // (up to half a second, never more than a tenth of the record).
    bands.f_high = std::min({10000.0, r.sample_rate / 4.5, r.highest_band_hz});
    bands.settle_time = std::min(0.5, 0.1 * duration);
    try {
      report.spectra.push_back(band_spectrum(p, r.sample_rate, bands));
    } catch (const InputError& error) {
      throw InputError(source, r.name, "too short or too coarsely sampled for band levels: " + error.problem());
    }
    report.levels[r.name] = {{"Leq_dB", leq_db(p)},
                             {"LAeq_dB", laeq_db(p, r.sample_rate)},
                             {"LAFmax_dB", lafmax_db(p, r.sample_rate)},
                             {"sample_rate_hz", r.sample_rate},
                             {"duration_s", duration}};
  }
  return report;
}

void write_sound_report(const fs::path& dir, const std::vector<ReceiverSignal>& signals, const SoundReport& report,
                        bool plot, PlotBatch* batch) {
  std::ofstream csv_file(dir / "spectrum.csv", std::ios::binary);
  csv_file << "receiver,band_hz,Lp_dB,LpA_dB\n";
  for (std::size_t i = 0; i < signals.size(); ++i) {
    const BandSpectrum& spectrum = report.spectra[i];
    for (std::size_t b = 0; b < spectrum.lp_db.size(); ++b) {
      csv_file << signals[i].name << ',' << spectrum.labels[b] << ',' << format_number(spectrum.lp_db[b]) << ','
               << format_number(spectrum.lpa_db[b]) << '\n';
    }
  }
  close_output_file(csv_file, dir / "spectrum.csv");
  if (plot) plot_spectra(dir, signals, batch);
}

nlohmann::json write_sound_report(const fs::path& dir, const std::vector<ReceiverSignal>& signals,
                                  const std::string& source, bool plot, std::vector<BandSpectrum>* spectra,
                                  PlotBatch* batch) {
  SoundReport report = sound_report(signals, source);
  write_sound_report(dir, signals, report, plot, batch);
  if (spectra) spectra->insert(spectra->end(), report.spectra.begin(), report.spectra.end());
  return report.levels;
}

}  // namespace rollnoise
