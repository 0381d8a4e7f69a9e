#pragma once
// budget.csv, budget.gp and budget.png of a tyre run with radiation (issue 10 §1, "an energy
// budget, band by band"): one run followed through the chain, per third-octave band (IEC 61260-1
// nominal centres), each line beside an independent estimate:
//   road texture as sampled (f = v/λ) → total contact force → belt velocity → radiated power
//   and radiation efficiency → level at each receiver.
// The numbers come from the library (acoustics/band_power, contact/texture_under_contact,
// contact/contact_force_estimate, greens/plate_mobility_average, radiation/radiation_efficiency);
// this file gathers them from the stages of one run and writes them.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "acoustics/band_power.hpp"
#include "acoustics/sound_levels.hpp"
#include "core/gnuplot.hpp"
#include "contact/rolling_tyre.hpp"
#include "contact/texture_under_contact.hpp"
#include "contact/tyre_grid.hpp"
#include "greens/kropp_plate.hpp"
#include "radiation/equivalent_sources.hpp"
#include "radiation/receivers.hpp"
#include "radiation/tyre_radiation.hpp"

namespace rollnoise {

// The arc distance from the contact (m) within which belt points count as "near the contact".
inline constexpr double budget_near_contact_m = 0.3;
// The Welch segment of every budget line is at most this long (samples).
inline constexpr std::size_t budget_max_segment = 1024;

// The contact and response lines of the budget (band mean squares in SI units: m², N², (m/s)²).
struct TyreBudget {
  std::vector<FractionalOctaveBand> bands;
  double speed = 0.0;        // m/s
  double sample_rate = 0.0;  // Hz, of the contact steps
  std::size_t segment_length = 0;
  double contact_stiffness = 0.0;  // k_c, N/m, of the estimate
  double patch_length = 0.0;       // m, mean over the run
  double patch_width = 0.0;        // m, mean over the run
  std::vector<double> texture_centre, texture_patch, force, v2_tread, v2_contact;
  // Force estimates: centre-line texture on the point receptance; patch-mean texture on the point
  // receptance; patch-mean texture on the patch receptance (a rigid patch).
  std::vector<double> force_estimate_point, force_estimate_patch, force_estimate_rigid_patch;
  std::vector<double> v2_tread_estimate, v2_contact_estimate;
};

// The bands of the budget for contact steps at `sample_rate`: 100 Hz up to the band nearest
// top_hz/2^(1/6), and none whose upper edge passes fs/2.
std::vector<FractionalOctaveBand> budget_bands(double sample_rate, double top_hz);

// Weights over the belt field (index j + Ny·g of SurfaceResponse's Ny × Nθ matrices, uniform
// cells): [0] the whole belt, [1] the positions within budget_near_contact_m of the bottom.
std::vector<std::vector<double>> belt_budget_weights(int around, int across, double circumference);

// The contact and response lines, and their estimates. belt_psd: the belt velocity's PSD
// averaged with belt_budget_weights. texture: the road under the window, gathered step by step. contact_stiffness: k_c of the single-point estimate.
TyreBudget tyre_budget(const TyreContactTrace& trace, const TextureUnderContact& texture, const KroppPlate& plate,
                       const PointAveragedPsd& belt_psd, double speed, double sample_rate,
                       std::vector<FractionalOctaveBand> bands, double contact_stiffness);

// The PSD of the radiating velocity, the budget's "v2_radiating" line: the Welch PSD of each of
// the mesh's tread cells (samples pushed one at a time, tread_points each: the radiation stage's
// input, contact cells silenced), averaged with the cells' areas as weights. It takes the
// samples as the run makes them, so a run need not keep them (issue 13).
std::unique_ptr<PointAveragedPsd> radiating_velocity_psd(const TyreSurfaceMesh& mesh, double sample_rate,
                                                         std::size_t segment_length);

// Adds the radiation lines and writes budget.csv. tyre_radius (m): of the pulsating cylinder
// of the σ estimate; the piston has the tread's area. air_pumping_power: the air pumping's power
// on the sound's bins (W; none: no air pumping), its own line Lw_air_pumping_dB_re_1pW beside
// the vibration's Lw (`sound` is the vibration alone); the receivers' levels hold both. (and budget.gp/png into `plots` when there is one). Returns the
// summary entry "energy_budget" (file name, bands, settings of the estimates).
nlohmann::json write_energy_budget(const std::filesystem::path& dir, const TyreBudget& budget,
                                   const RadiatedSound& sound, const PointAveragedPsd& radiating,
                                   const TyreSurfaceMesh& mesh, double tyre_radius, const Medium& medium,
                                   const std::vector<Receiver>& receivers, const std::vector<BandSpectrum>& spectra,
                                   PlotBatch* plots, const Eigen::VectorXd* air_pumping_power = nullptr);

}  // namespace rollnoise
