#include "greens/rolling_tyre_model.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/config_table.hpp"
#include "core/error.hpp"
#include "greens/fitted_modes_cache.hpp"
#include "greens/modal_table_cache.hpp"
#include "greens/static_residual.hpp"
#include "greens/tabulated_factory.hpp"
#include "greens/two_layer_factory.hpp"

namespace rollnoise {

namespace {

RollingTyreModel plate_model(const PlateTyre& file) {
  RollingTyreModel out;
  out.model = "plate";
  out.modes = std::make_unique<KroppPlate>(file.plate);
  out.radius = file.plate.radius;
  out.width = file.plate.width;
  out.crown_radius = file.crown_radius;
  out.tread_width = file.tread_width;
  out.tread = file.tread;
  out.plate = file.plate;
  out.tread_youngs_modulus = file.tread.youngs_modulus;
  out.tread_poisson_ratio = file.tread.poisson_ratio;
  out.belt_tension = file.plate.tension_x;
  out.belt_bending = file.plate.bending_x;
  out.foundation_stiffness = file.plate.foundation_stiffness;
  return out;
}

// A model whose table is of the tread surface carries its tread: a [tyre.tread] table is then
// a contradiction, not an addition.
void reject_separate_tread(const ConfigTable& tyre, const std::string& model) {
  if (tyre.contains("tread"))
    tyre.fail("tread", "is not used by model = \"" + model +
                           "\", which includes the tread's local deformation: remove the [tyre.tread] table");
}

// The fits come from the cache under `fit_key` when it has them (their errors measured again
// against the table), otherwise they are made and stored there.
RollingTyreModel fitted_model(std::string model, ModalReceptanceTable table, double seconds, bool from_cache,
                              const std::optional<std::filesystem::path>& cache_directory, const std::string& fit_key) {
  RollingTyreModel out;
  out.model = model;
  out.radius = table.radius;
  out.width = table.width;
  out.table_seconds = seconds;
  out.table_from_cache = from_cache;
  bool fits_from_cache = false;
  auto fitted = std::make_unique<FittedModalTyre>(
      fit_with_cache(std::move(table), std::move(model), cache_directory, fit_key, fits_from_cache));
  out.fits_from_cache = fits_from_cache;
  out.fit = fitted->fit_report();
  out.modes = std::move(fitted);
  return out;
}

// H_zz(k, ω = 0) of the layers for the modes beyond the table, where the wavenumber is high
// enough (k ≥ the first left-out order's, ~450 rad/m for the passenger tyre: wavelengths under
// 14 mm, a tread-thickness or two) that the tread carries the response and the belt's
// orthotropy no longer matters: the exact stack along the diagonal k_x = k_y, sampled on a
// logarithmic grid in |k| and interpolated log–log. For the passenger file the direction changes
// it by at most 0.33 % from 450 rad/m on (tests/greens/test_static_residual.cpp).
std::function<double(double, double)> layer_static_compliance(const TwoLayerTyre& layers, double k_low, double k_high) {
  constexpr int samples = 400;
  auto log_k = std::make_shared<std::vector<double>>(samples);
  auto log_h = std::make_shared<std::vector<double>>(samples);
  const double a = std::log(k_low), b = std::log(k_high);
  for (int s = 0; s < samples; ++s) {
    const double lk = a + (b - a) * s / (samples - 1);
    const double k = std::exp(lk) / std::sqrt(2.0);
    (*log_k)[static_cast<std::size_t>(s)] = lk;
    (*log_h)[static_cast<std::size_t>(s)] = std::log(layers.wavenumber_compliance(k, k, 0.0)(2, 2).real());
  }
  return [log_k, log_h, a, b](double kx, double ky) {
    const double lk = std::clamp(0.5 * std::log(kx * kx + ky * ky), a, b);
    const double where = (lk - a) / (b - a) * (samples - 1);
    const auto s = std::min(static_cast<std::size_t>(where), std::size_t{samples - 2});
    const double t = where - static_cast<double>(s);
    return std::exp((1.0 - t) * (*log_h)[s] + t * (*log_h)[s + 1]);
  };
}

}  // namespace

RollingTyreSpec read_rolling_tyre_spec(const ConfigTable& tyre) {
  RollingTyreSpec spec;
  spec.model = tyre.choice("model", {"plate", "two_layer", "tabulated"});
  if (spec.model == "plate") {
    spec.plate = read_plate_tyre(tyre);
    spec.radius = spec.plate->plate.radius;
    spec.width = spec.plate->plate.width;
    spec.tread_width = spec.plate->tread_width;
    return spec;
  }
  if (spec.model == "two_layer") {
    reject_separate_tread(tyre, spec.model);
    spec.two_layer = std::make_shared<const TwoLayerParameters>(read_two_layer_tyre(tyre));
    spec.radius = spec.two_layer->radius;
    spec.width = spec.two_layer->width;
    spec.tread_width = spec.two_layer->tread_width > 0.0 ? spec.two_layer->tread_width : spec.two_layer->width;
  } else {
    // A table holds its modes up to its orders and nothing beyond them: the contact cells get no
    // local compliance from it (the two-layer model adds its static residual, the plate its
    // tread), and the contact matrix of a table alone is close to singular. The tread says what
    // the table lacks. A misspelt key is reported first; a missing tread is named in the file that
    // says model = "tabulated" (a model file, or the case itself).
    reject_unknown_tabulated_keys(tyre);
    if (!tyre.contains("tread"))
      throw InputError(tyre.source_of("model"), "[tyre] tread",
                       "is required with model = \"tabulated\" to roll: a table holds its modes up to its orders "
                       "and no local compliance of the contact cells beyond them; give the tread's, a [tyre.tread] "
                       "table with type = \"winkler\" (stiffness_per_area), \"halfspace\" or \"nonlinear\"");
    spec.tread = read_tread(tyre);
    spec.table = read_tabulated_tyre(tyre);
    spec.radius = spec.table->radius;
    spec.width = spec.table->width;
    spec.tread_width = spec.table->width;
  }
  return spec;
}

RollingTyreModel make_rolling_tyre_model(RollingTyreSpec spec, const std::optional<std::filesystem::path>& cache_directory) {
  const std::string& model = spec.model;
  if (spec.plate) return plate_model(*spec.plate);
  const auto started = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
  if (spec.two_layer) {
    const TwoLayerParameters& p = *spec.two_layer;
    const TwoLayerTyre layers(p);
    const Eigen::VectorXd frequencies = tyre_mode_fit_frequencies();
    ModalReceptanceTable table = cached_two_layer_table(layers, frequencies, p.circumferential_modes, cache_directory);
    const bool from_cache = table.source != "two_layer";
    const std::string fit_key =
        fitted_modes_key(two_layer_table_key(p, p.circumferential_modes, frequencies), tyre_mode_fit_options());
    RollingTyreModel out = fitted_model(model, std::move(table), elapsed(), from_cache, cache_directory, fit_key);
    out.crown_radius = p.crown_radius;
    out.tread_width = p.tread_width > 0.0 ? p.tread_width : p.width;
    out.tread_youngs_modulus = p.tread_youngs_modulus;
    out.tread_poisson_ratio = p.tread_poisson_ratio;
    out.belt_tension = p.tension_x;
    // E_x·h³/12: the belt's bending along the circumference (the plate file's bending_x).
    out.belt_bending = p.belt.youngs_x * p.belt_thickness * p.belt_thickness * p.belt_thickness / 12.0;
    out.foundation_stiffness = p.foundation_stiffness;
    KeptModes kept;
    kept.circumference = 2.0 * std::numbers::pi * p.radius;
    kept.width = p.width;
    kept.lateral_shape = p.side_condition == SideCondition::sliding ? LateralShape::cosine : LateralShape::sine;
    kept.first_lateral_order = layers.first_lateral_order();
    kept.lateral_orders = p.lateral_modes;
    kept.orders = p.circumferential_modes;
    out.residual = [kept, p](int window, double dx, std::span<const double> y, double dy) {
      const TwoLayerTyre stack(p);
      const double k_low = std::min(2.0 * std::numbers::pi * (kept.orders + 1) / kept.circumference,
                                    (kept.first_lateral_order + kept.lateral_orders) * std::numbers::pi / kept.width);
      const double k_high = 16.0 * std::numbers::pi / std::min(dx, dy);
      return static_residual_compliance(kept, layer_static_compliance(stack, k_low, k_high), window, dx, y, dy);
    };
    return out;
  }
  ModalReceptanceTable table = std::move(*spec.table);
  const std::string fit_key = fitted_modes_key(modal_table_content_key(table), tyre_mode_fit_options());
  RollingTyreModel out = fitted_model(model, std::move(table), elapsed(), false, cache_directory, fit_key);
  out.tread_width = out.width;
  out.tread = spec.tread;
  if (spec.tread) {
    out.tread_youngs_modulus = spec.tread->youngs_modulus;
    out.tread_poisson_ratio = spec.tread->poisson_ratio;
  }
  return out;
}

}  // namespace rollnoise
