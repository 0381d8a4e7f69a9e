#include "simulation/pattern_outputs.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "acoustics/band_power.hpp"
#include "acoustics/fractional_octave_bands.hpp"
#include "core/csv.hpp"
#include "core/gnuplot.hpp"
#include "core/output_directory.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

void write_tread_pattern_map(const fs::path& dir, const TreadPattern& pattern, double tread_width,
                             const std::string& title, PlotBatch* plots) {
  const double length = pattern.circumference();
  const auto around = static_cast<int>(std::lround(length / 0.002));
  const int across = std::max(2, static_cast<int>(std::lround(tread_width / 0.002)));
  const double ds = length / around, dy = tread_width / across;
  const fs::path path = dir / "tread_pattern.csv";
  std::ofstream out(path, std::ios::binary);
  {
    CsvWriter csv(out, {"s", "y", "height"});
    for (int i = 0; i < around; ++i) {
      for (int j = 0; j < across; ++j) {
        const double s = (i + 0.5) * ds, y = (j + 0.5) * dy - 0.5 * tread_width;
        const double row[] = {s, y, pattern.height(s, y)};
        csv.row(row, 3);
      }
      out << '\n';  // one scan line per s, as gnuplot's image style expects
    }
  }
  close_output_file(out, path);
  if (!plots) return;
  std::ostringstream gp;
  gp << "# Drawn by rollnoise from tread_pattern.csv; run `gnuplot tread_pattern.gp` to redraw.\n"
     << "# The tread unrolled: s around the circumference (2πR = " << length << " m) in four strips of a\n"
     << "# quarter turn, y across from the tread's centre line; height 0 is the block surface.\n"
     << "set terminal pngcairo size 1200,900 noenhanced font 'DejaVu Sans,10'\n"
     << "set output 'tread_pattern.png'\nset datafile separator ','\n"
     << "set palette defined (0 '#440154', 1 '#21918c', 2 '#fde725', 3 'white')\n"
     << "set cblabel 'tread height (mm)'\nset ylabel 'y (mm)'\n"
     << "set yrange [" << -500.0 * tread_width << ":" << 500.0 * tread_width << "]\n"
     << "set multiplot layout 4,1 title \"" << title << ": tread pattern, unrolled (a quarter turn per strip)\"\n";
  for (int k = 0; k < 4; ++k) {
    gp << "set xrange [" << k * 250.0 * length << ":" << (k + 1) * 250.0 * length << "]\n";
    if (k == 3) gp << "set xlabel 's around the circumference (mm)'\n";
    gp << "plot 'tread_pattern.csv' skip 1 using ($1*1e3):($2*1e3):($3*1e3) with image notitle\n";
  }
  gp << "unset multiplot\n";
  write_plot(dir, "tread_pattern", gp.str(), plots);
}

nlohmann::json pattern_tones(const TreadPattern& pattern, std::span<const double> total_force, double sample_rate,
                             double speed, int harmonics) {
  nlohmann::json out;
  const int order = pattern.tone_order();
  out["pitches"] = pattern.pitch_starts().size();
  out["tone_order"] = order;
  out["circumference_m"] = pattern.circumference();
  if (order == 0) {
    out["fundamental_hz"] = nullptr;
    out["tones"] = nlohmann::json::array();
    return out;
  }
  const double fundamental = order * speed / pattern.circumference();
  out["fundamental_hz"] = fundamental;
  out["level_above_neighbours"] =
      "L_b - (L_b-1 + L_b+1)/2: the tone's third-octave band level of the total contact force over the mean of its "
      "two neighbouring bands' levels (dB)";
  nlohmann::json tones = nlohmann::json::array();
  for (int k = 1; k <= harmonics; ++k) {
    const double f = k * fundamental;
    const int index = nearest_band_index(f, 3);
    const FractionalOctaveBand band = fractional_octave_band(index, 3);
    nlohmann::json tone = {{"harmonic", k}, {"frequency_hz", f}, {"band_hz", band.nominal}};
    const FractionalOctaveBand upper = fractional_octave_band(index + 1, 3);
    if (total_force.size() >= 8 && upper.upper < 0.5 * sample_rate) {
      const std::vector<FractionalOctaveBand> bands{fractional_octave_band(index - 1, 3), band, upper};
      const std::vector<double> ms =
          fluctuation_band_mean_squares(total_force, sample_rate, bands, welch_segment_for(total_force.size()));
      const double below = level_db(ms[0], 1.0), at = level_db(ms[1], 1.0), above = level_db(ms[2], 1.0);
      tone["band_level_dB_re_1N"] = at;
      tone["level_above_neighbours_dB"] = at - 0.5 * (below + above);
    } else {
      tone["band_level_dB_re_1N"] = nullptr;
      tone["level_above_neighbours_dB"] = nullptr;
    }
    tones.push_back(std::move(tone));
  }
  out["tones"] = std::move(tones);
  return out;
}

}  // namespace rollnoise
