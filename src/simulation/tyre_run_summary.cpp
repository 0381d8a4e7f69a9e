#include "simulation/tyre_run_summary.hpp"

#include <span>

#include "contact/tread_pattern.hpp"
#include "simulation/pattern_outputs.hpp"
#include "simulation/point_contact_output.hpp"

namespace rollnoise {

nlohmann::json tyre_contact_summary(const TyreRunFacts& f, const TyreContactTrace& trace) {
  nlohmann::json summary;
  summary["case"] = f.file.name();
  summary["paths_outside_case_folder"] = f.file.paths_outside_folder();  // via ".." or a symlink
  summary["tyre_file"] = f.file.tyre_file();        // as the case (or --set tyre.file) named it
  summary["surface_file"] = f.file.surface_file();  // likewise [road] surface
  summary["model"] = f.model.model;
  summary["tread"] = !f.model.tread                                         ? "included in the model"
                     : f.model.tread->type == TreadSettings::Type::winkler   ? "winkler"
                     : f.model.tread->type == TreadSettings::Type::halfspace ? "halfspace"
                                                                           : "nonlinear";
  if (f.model.fit) {
    summary["mode_fit"] = {{"modes", f.model.fit->modes},
                           {"poles", f.model.fit->poles},
                           {"unconverged_modes", f.model.fit->unconverged},
                           {"worst_relative_rms_error", f.model.fit->worst_rms_error},
                           {"mean_relative_rms_error", f.model.fit->mean_rms_error},
                           {"worst_relative_max_error", f.model.fit->worst_max_error},
                           {"worst_mode", {f.model.fit->worst_order, f.model.fit->worst_lateral_order}},
                           {"fit_time_s", f.model.fit->seconds},
                           {"table_time_s", f.model.table_seconds},
                           {"table_from_cache", f.model.table_from_cache},
                           {"fits_from_cache", f.model.fits_from_cache}};
  }
  summary["road"] = f.road_type;
  if (f.pattern)
    summary["tread_pattern"] = pattern_tones(
        *f.pattern, std::span<const double>(trace.total_force.data(), static_cast<std::size_t>(trace.total_force.size())),
        1.0 / f.dt, f.settings.speed);
  summary["contact_h5_fields"] = to_string(f.fields);
  summary["mean_total_force_N"] = trace.total_force.mean();
  summary["max_total_force_N"] = trace.total_force.maxCoeff();
  summary["min_total_force_N"] = trace.total_force.minCoeff();
  summary["mean_contact_area_m2"] = trace.contact_area.mean();
  summary["patch_length_m"] = trace.contact_length.mean();
  summary["patch_width_m"] = trace.contact_width.mean();
  summary["rolling_resistance_N"] = trace.input_power.mean() / f.settings.speed;
  summary["steady_rolling_resistance_N"] = trace.steady_rolling_resistance;
  summary["indentation_m"] = trace.indentation;
  summary["history_engine"] = trace.engine;
  summary["lcp_iterations"] = summarise_iterations(trace.lcp_iterations);
  summary["state_changes"] = summarise_iterations(trace.state_changes);
  const ContactMatrixStructure& g0 = trace.contact_matrix;
  summary["contact_matrix"] = {{"diagonal_dominance_min", g0.diagonal_dominance_min},
                               {"diagonal_dominance_median", g0.diagonal_dominance_median},
                               {"offsets_cells", g0.offsets},
                               {"decay_x", g0.decay_x},
                               {"decay_y", g0.decay_y},
                               {"translation_variance", g0.translation_variance},
                               {"skewness", g0.skewness}};
  summary["contact_matrix_skewness"] = trace.contact_matrix_skewness;
  summary["lagged_skew_growth"] = trace.lagged_skew_growth;
  summary["contact_step"] = trace.skew_part_lagged ? "symmetric LCP, G0's skew part one step late"
                                                   : "P-matrix LCP with the whole G0";
  if (f.settings.contact_law == ContactLaw::texture) {
    summary["contact_step"] = trace.skew_part_lagged
                                  ? "texture laws in series (Newton over contact sets), G0's skew part one step late"
                                  : "texture laws in series (Newton over contact sets) with the whole G0";
    summary["texture_contact_law"] = {{"cells", trace.law_cells},
                                      {"pixels_along", trace.law_pixels.nx},
                                      {"pixels_across", trace.law_pixels.ny},
                                      {"road_samples_per_pixel", trace.law_pixels.samples},
                                      {"pixel_m", f.grid.dx() / static_cast<double>(trace.law_pixels.nx)},
                                      {"tread_youngs_modulus_Pa", f.model.tread_youngs_modulus},
                                      {"tread_poisson_ratio", f.model.tread_poisson_ratio},
                                      {"force_cap_N", trace.law_force_cap},
                                      {"largest_cell_force_N", trace.largest_cell_force},
                                      {"seconds", trace.law_seconds},
                                      {"from_cache", trace.laws_from_cache}};
  }
  summary["grid"] = {{"points_circumferential", f.grid.circumferential},
                     {"points_lateral", f.grid.lateral},
                     {"contact_window_points", f.grid.window},
                     {"dx_m", f.grid.dx()},
                     {"dy_m", f.grid.dy()},
                     {"contact_points", f.grid.points()}};
  summary["settings"] = {{"speed_m_per_s", f.settings.speed},
                         {"duration_s", f.settings.duration},
                         {"time_step_s", f.dt},
                         {"substeps", f.substeps},
                         {"road_sampling", f.settings.road_sampling == RoadSampling::point       ? "point"
                                           : f.settings.road_sampling == RoadSampling::lowpass ? "lowpass"
                                                                                             : "cell_mean"},
                         {"contact_law", f.settings.contact_law == ContactLaw::texture ? "texture" : "rigid"},
                         {"band_top_hz", f.settings.band_top},
                         {"contact_nyquist_hz", 0.5 / f.dt},
                         {"steps", f.steps},
                         {"static_load_N", f.settings.static_load},
                         {"history", to_string(f.settings.history)}};
  return summary;
}

}  // namespace rollnoise
