#include "simulation/energy_budget_output.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "contact/contact_force_estimate.hpp"
#include "contact/texture_under_contact.hpp"
#include "core/csv.hpp"
#include "core/output_directory.hpp"
#include "core/gnuplot.hpp"
#include "greens/plate_mobility_average.hpp"
#include "radiation/radiation_efficiency.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

constexpr double texture_reference = 1e-6;   // m
constexpr double force_reference = 1.0;      // N
constexpr double velocity_reference = 1e-9;  // m/s
constexpr double power_reference = 1e-12;    // W

// The horn gain measured with the default mesh, the loaded tyre (docs/physics/radiation.md, "The horn";
// test_horn_effect.cpp): the middle of each range over the three receivers in the tyre plane,
// 0.5–1 m ahead, 5–20 cm high, source 5 cm ahead of the patch edge (500 Hz 11.1–12.2, 1 kHz
// 13.7–14.6, 2 kHz 5.4–7.9 dB, the last not converged: the reciprocal estimate is 4 dB higher),
// linear in lg f between them and held beyond (not measured there).
double horn_gain_db(double f) {
  const double lf[] = {std::log10(500.0), std::log10(1000.0), std::log10(2000.0)};
  const double g[] = {11.6, 14.2, 6.6};
  const double x = std::clamp(std::log10(f), lf[0], lf[2]);
  const int i = x <= lf[1] ? 0 : 1;
  return g[i] + (g[i + 1] - g[i]) * (x - lf[i]) / (lf[i + 1] - lf[i]);
}

std::vector<double> times(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> c(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) c[i] = a[i] * b[i];
  return c;
}

}  // namespace

std::vector<FractionalOctaveBand> budget_bands(double sample_rate, double top_hz) {
  const double nyquist = 0.5 * sample_rate;
  const double top = std::max(100.0, std::min(top_hz, nyquist) / std::pow(2.0, 1.0 / 6.0));
  std::vector<FractionalOctaveBand> bands = fractional_octave_bands(3, 100.0, top);
  std::erase_if(bands, [&](const FractionalOctaveBand& b) { return b.upper > nyquist; });
  if (bands.empty()) throw std::invalid_argument("budget_bands: no band from 100 Hz fits below fs/2");
  return bands;
}

std::vector<std::vector<double>> belt_budget_weights(int around, int across, double circumference) {
  std::vector<std::vector<double>> w(2, std::vector<double>(static_cast<std::size_t>(around) * across, 0.0));
  const double dx = circumference / around;
  for (int g = 0; g < around; ++g) {
    const double arc = std::min(g, around - g) * dx;  // from the bottom, either way round
    for (int j = 0; j < across; ++j) {
      const std::size_t p = static_cast<std::size_t>(j) + static_cast<std::size_t>(across) * g;
      w[0][p] = 1.0;
      w[1][p] = arc <= budget_near_contact_m + 1e-12 ? 1.0 : 0.0;
    }
  }
  return w;
}

TyreBudget tyre_budget(const TyreContactTrace& trace, const TextureUnderContact& texture, const KroppPlate& plate,
                       const PointAveragedPsd& belt_psd, double speed, double sample_rate,
                       std::vector<FractionalOctaveBand> bands, double contact_stiffness) {
  TyreBudget b;
  b.bands = std::move(bands);
  b.speed = speed;
  b.sample_rate = sample_rate;
  b.segment_length = welch_segment_for(static_cast<std::size_t>(trace.time.size()), budget_max_segment);
  b.contact_stiffness = contact_stiffness;
  b.patch_length = trace.contact_length.mean();
  b.patch_width = std::min(trace.contact_width.mean(), plate.parameters().width);

  // Texture: the centre line(s), band powers averaged over the lines; and the patch mean.
  const std::vector<std::vector<double>>& lines = texture.centre_lines();
  b.texture_centre.assign(b.bands.size(), 0.0);
  for (const std::vector<double>& line : lines) {
    const std::vector<double> ms = fluctuation_band_mean_squares(line, sample_rate, b.bands, b.segment_length);
    for (std::size_t i = 0; i < ms.size(); ++i) b.texture_centre[i] += ms[i] / static_cast<double>(lines.size());
  }
  b.texture_patch = fluctuation_band_mean_squares(texture.patch_mean(b.patch_length), sample_rate, b.bands,
                                                  b.segment_length);
  const std::span<const double> force(trace.total_force.data(), static_cast<std::size_t>(trace.total_force.size()));
  b.force = fluctuation_band_mean_squares(force, sample_rate, b.bands, b.segment_length);
  b.v2_tread = band_mean_squares_from_psd(belt_psd.average(0), b.bands);
  b.v2_contact = band_mean_squares_from_psd(belt_psd.average(1), b.bands);

  // Independent estimates: the single-point contact, and the belt's mean-square mobility.
  const double y0 = 0.5 * plate.parameters().width;
  const double two_pi = 2.0 * std::numbers::pi;
  const std::vector<double> transfer = band_means_of(
      b.bands, [&](double f) { return single_point_force_transfer(plate, contact_stiffness, y0, two_pi * f); });
  b.force_estimate_point = times(transfer, b.texture_centre);
  b.force_estimate_patch = times(transfer, b.texture_patch);
  const std::vector<double> rigid_patch = band_means_of(b.bands, [&](double f) {
    const std::complex<double> c =
        1.0 / contact_stiffness + patch_receptance(plate, b.patch_length, b.patch_width, two_pi * f);
    return 1.0 / std::norm(c);
  });
  b.force_estimate_rigid_patch = times(rigid_patch, b.texture_patch);
  const std::vector<double> y2_belt =
      band_means_of(b.bands, [&](double f) { return belt_mean_square_mobility(plate, y0, two_pi * f); });
  const NearMeanSquareMobility near_mobility(plate, y0, budget_near_contact_m);
  const std::vector<double> y2_near = band_means_of(b.bands, [&](double f) { return near_mobility(two_pi * f); });
  b.v2_tread_estimate = times(y2_belt, b.force);
  b.v2_contact_estimate = times(y2_near, b.force);
  return b;
}

std::unique_ptr<PointAveragedPsd> radiating_velocity_psd(const TyreSurfaceMesh& mesh, double sample_rate,
                                                         std::size_t segment_length) {
  const auto tread = static_cast<std::size_t>(mesh.tread_points);
  std::vector<double> areas(mesh.areas.data(), mesh.areas.data() + tread);
  return std::make_unique<PointAveragedPsd>(tread, sample_rate, segment_length, std::vector<std::vector<double>>{areas});
}

nlohmann::json write_energy_budget(const fs::path& dir, const TyreBudget& budget, const RadiatedSound& sound,
                                   const PointAveragedPsd& radiating, const TyreSurfaceMesh& mesh,
                                   double tyre_radius, const Medium& medium, const std::vector<Receiver>& receivers,
                                   const std::vector<BandSpectrum>& spectra, PlotBatch* plots,
                                   const Eigen::VectorXd* air_pumping_power) {
  const std::vector<FractionalOctaveBand>& bands = budget.bands;
  // Radiated power per band, from the radiation stage's bins.
  const std::vector<double> power =
      band_sums(std::span<const double>(sound.frequency_hz.data(), static_cast<std::size_t>(sound.frequency_hz.size())),
                std::span<const double>(sound.sound_power_w.data(), static_cast<std::size_t>(sound.sound_power_w.size())),
                bands);
  std::vector<double> air_power;
  if (air_pumping_power)
    air_power = band_sums(std::span<const double>(sound.frequency_hz.data(), static_cast<std::size_t>(sound.frequency_hz.size())),
                          std::span<const double>(air_pumping_power->data(), static_cast<std::size_t>(air_pumping_power->size())),
                          bands);
  // The radiating velocity: the mesh's tread cells (contact cells silenced), area-weighted.
  const auto tread = static_cast<std::size_t>(mesh.tread_points);
  double area = 0.0;
  for (std::size_t p = 0; p < tread; ++p) area += mesh.areas(static_cast<Eigen::Index>(p));
  const std::vector<double> v2_radiating = band_mean_squares_from_psd(radiating.average(0), bands);

  // Receivers: their band levels (spectrum.csv) where every receiver has the band.
  std::vector<std::size_t> rows;
  std::vector<std::vector<std::size_t>> at(receivers.size());
  for (std::size_t b = 0; b < bands.size(); ++b) {
    bool all = true;
    std::vector<std::size_t> found(receivers.size());
    for (std::size_t r = 0; r < receivers.size() && r < spectra.size(); ++r) {
      const auto& nominal = spectra[r].nominal_hz;
      const auto it = std::find_if(nominal.begin(), nominal.end(),
                                   [&](double f) { return std::abs(f - bands[b].nominal) < 1e-6 * f; });
      if (it == nominal.end()) all = false;
      else found[r] = static_cast<std::size_t>(it - nominal.begin());
    }
    if (!all || spectra.size() < receivers.size()) continue;
    rows.push_back(b);
    for (std::size_t r = 0; r < receivers.size(); ++r) at[r].push_back(found[r]);
  }

  std::vector<std::string> header{"band_hz",
                                  "wavelength_m",
                                  "texture_centre_dB_re_1um",
                                  "texture_patch_dB_re_1um",
                                  "force_dB_re_1N",
                                  "force_est_point_dB_re_1N",
                                  "force_est_patch_dB_re_1N",
                                  "force_est_rigid_patch_dB_re_1N",
                                  "v2_tread_dB_re_1nm_s",
                                  "v2_contact_dB_re_1nm_s",
                                  "v2_tread_est_dB_re_1nm_s",
                                  "v2_contact_est_dB_re_1nm_s",
                                  "v2_radiating_dB_re_1nm_s",
                                  "Lw_dB_re_1pW",
                                  "sigma",
                                  "sigma_piston",
                                  "sigma_cylinder"};
  for (const Receiver& r : receivers) {
    header.push_back("Lp_" + r.name + "_dB_re_20uPa");
    header.push_back("Lp_" + r.name + "_hemi_est_dB_re_20uPa");
  }
  header.push_back("horn_gain_dB");
  if (air_pumping_power) header.push_back("Lw_air_pumping_dB_re_1pW");
  std::ofstream out(dir / "budget.csv", std::ios::binary);
  CsvWriter csv(out, header);
  const double rho_c = medium.density * medium.sound_speed;
  const double piston_radius = std::sqrt(area / std::numbers::pi);
  std::vector<double> values(header.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::size_t b = rows[k];
    const FractionalOctaveBand& band = bands[b];
    const double ka = 2.0 * std::numbers::pi * band.exact / medium.sound_speed;
    const double lw = level_db(power[b], std::sqrt(power_reference));
    std::size_t c = 0;
    values[c++] = band.nominal;
    values[c++] = budget.speed / band.exact;
    values[c++] = level_db(budget.texture_centre[b], texture_reference);
    values[c++] = level_db(budget.texture_patch[b], texture_reference);
    values[c++] = level_db(budget.force[b], force_reference);
    values[c++] = level_db(budget.force_estimate_point[b], force_reference);
    values[c++] = level_db(budget.force_estimate_patch[b], force_reference);
    values[c++] = level_db(budget.force_estimate_rigid_patch[b], force_reference);
    values[c++] = level_db(budget.v2_tread[b], velocity_reference);
    values[c++] = level_db(budget.v2_contact[b], velocity_reference);
    values[c++] = level_db(budget.v2_tread_estimate[b], velocity_reference);
    values[c++] = level_db(budget.v2_contact_estimate[b], velocity_reference);
    values[c++] = level_db(v2_radiating[b], velocity_reference);
    values[c++] = lw;
    values[c++] = v2_radiating[b] > 0.0
                      ? radiation_efficiency(power[b], medium.density, medium.sound_speed, area, v2_radiating[b])
                      : 0.0;
    values[c++] = baffled_piston_radiation_efficiency(ka * piston_radius);
    values[c++] = pulsating_cylinder_radiation_efficiency(ka * tyre_radius);
    for (std::size_t r = 0; r < receivers.size(); ++r) {
      values[c++] = spectra[r].lp_db[at[r][k]];
      const double distance = receivers[r].position.norm();
      values[c++] = lw - 10.0 * std::log10(2.0 * std::numbers::pi * distance * distance) + 10.0 * std::log10(rho_c / 400.0);
    }
    values[c++] = horn_gain_db(band.exact);
    if (air_pumping_power) values[c++] = level_db(air_power[b], std::sqrt(power_reference));
    for (double& v : values)
      if (!std::isfinite(v)) v = -999.0;  // a zero power: no level (the CSV holds finite numbers)
    csv.row(values.data(), values.size());
  }
  close_output_file(out, dir / "budget.csv");

  if (plots) {
    // Columns (1-based) of the lines drawn.
    const std::size_t lp = 18;  // Lp of the first receiver
    std::ostringstream gp;
    gp << "# Drawn by rollnoise from budget.csv; run `gnuplot budget.gp` to redraw.\n"
       << "# The energy budget of the run, band by band: each stage (solid) and its independent estimate\n"
       << "# (dashed). Levels: texture dB re 1 um, force dB re 1 N, velocity dB re 1e-9 m/s, power dB re 1 pW,\n"
       << "# pressure dB re 20 uPa. Radiation efficiency on the right axis.\n"
       << "set terminal pngcairo size 1200,650 noenhanced font 'DejaVu Sans,10'\n"
       << "set output 'budget.png'\nset datafile separator ','\nset grid\nset logscale x\n"
       << "set xlabel 'third-octave band (Hz)'\nset ylabel 'level (dB, references in the key)'\n"
       << "set y2label 'radiation efficiency sigma'\nset logscale y2\nset y2range [1e-3:10]\nset ytics nomirror\n"
       << "set y2tics\nset yrange [-20:*]\nset autoscale xfix\nset key outside right font 'DejaVu Sans,9'\n"
       << "set title 'Energy budget: texture -> force -> belt velocity -> sound power -> microphone'\n"
       << "plot 'budget.csv' skip 1 using 1:3 with linespoints lw 1.5 pt 7 ps 0.5 lc 1 title 'texture, centre line (re 1 um)', \\\n"
       << "     '' skip 1 using 1:4 with lines dt 2 lc 1 title 'texture, patch mean', \\\n"
       << "     '' skip 1 using 1:5 with linespoints lw 1.5 pt 7 ps 0.5 lc 2 title 'total force (re 1 N)', \\\n"
       << "     '' skip 1 using 1:6 with lines dt 2 lc 2 title 'force est., point texture', \\\n"
       << "     '' skip 1 using 1:7 with lines dt 3 lc 2 title 'force est., patch texture', \\\n"
       << "     '' skip 1 using 1:8 with lines dt 4 lc 2 title 'force est., rigid patch', \\\n"
       << "     '' skip 1 using 1:9 with linespoints lw 1.5 pt 7 ps 0.5 lc 3 title '<v2> belt (re 1e-9 m/s)', \\\n"
       << "     '' skip 1 using 1:10 with linespoints lw 1.5 pt 5 ps 0.5 lc 4 title '<v2> within 0.3 m of contact', \\\n"
       << "     '' skip 1 using 1:11 with lines dt 2 lc 3 title '<v2> belt est. |Y|2 F2', \\\n"
       << "     '' skip 1 using 1:12 with lines dt 2 lc 4 title '<v2> near est. |Y|2 F2', \\\n"
       << "     '' skip 1 using 1:13 with lines lw 1 lc 8 title '<v2> radiating (mesh)', \\\n"
       << "     '' skip 1 using 1:14 with linespoints lw 1.5 pt 7 ps 0.5 lc 6 title 'L_W (re 1 pW)', \\\n";
    if (air_pumping_power)
      gp << "     '' skip 1 using 1:" << header.size() << " with linespoints lw 1.5 pt 6 ps 0.6 lc 5 title 'L_W air pumping', \\\n";
    if (!receivers.empty()) {
      gp << "     '' skip 1 using 1:" << lp << " with linespoints lw 1.5 pt 9 ps 0.6 lc 7 title 'L_p " << receivers[0].name
         << "', \\\n"
         << "     '' skip 1 using 1:" << lp + 1 << " with lines dt 2 lc 7 title 'L_p " << receivers[0].name
         << " est. (hemisphere, no horn)', \\\n";
    }
    gp << "     '' skip 1 using 1:15 axes x1y2 with linespoints lw 2 pt 4 ps 0.6 lc rgb 'black' title 'sigma (right)', \\\n"
       << "     '' skip 1 using 1:16 axes x1y2 with lines dt 2 lc rgb 'black' title 'sigma piston (right)', \\\n"
       << "     '' skip 1 using 1:17 axes x1y2 with lines dt 3 lc rgb 'black' title 'sigma cylinder (right)'\n";
    write_plot(dir, "budget", gp.str(), plots);
  }
  return {{"file", "budget.csv"},
          {"bands", rows.size()},
          {"welch_segment_samples", budget.segment_length},
          {"contact_stiffness_N_per_m", budget.contact_stiffness},
          {"patch_length_m", budget.patch_length},
          {"patch_width_m", budget.patch_width},
          {"near_contact_m", budget_near_contact_m},
          {"radiating_area_m2", area}};
}

}  // namespace rollnoise
