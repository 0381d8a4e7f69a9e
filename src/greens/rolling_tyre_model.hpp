#pragma once
// The tyre of a rolling case, whichever its model (issue 11, "any tyre model rolls"): its modes
// for the rolling code (modal_tyre.hpp), the separate tread that only the plate needs, the
// contact geometry, and the few figures later stages take from it. The plate is exact; the
// two-layer tyre is tabulated per mode (cached by a digest of its parameters) and fitted with
// poles (fitted_modal_tyre.hpp).
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <optional>
#include <string>

#include "greens/fitted_modal_tyre.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/modal_receptance_table.hpp"
#include "greens/modal_tyre.hpp"
#include "greens/plate_factory.hpp"

namespace rollnoise {

class ConfigTable;
struct TwoLayerParameters;

struct RollingTyreModel {
  std::string model;                 // "plate" | "two_layer" | "tabulated"
  std::unique_ptr<ModalTyre> modes;  // what rolls
  double radius = 0.0;               // m
  double width = 0.0;                // m, the span of the lateral shapes
  double crown_radius = 0.0;         // m, 0 = flat across
  double tread_width = 0.0;          // m, the width that meets the road
  // The plate's separate tread ([tyre.tread]); absent for models that include their tread.
  std::optional<TreadSettings> tread;
  std::optional<PlateParameters> plate;  // the plate's parameters (the energy budget's estimates)
  // The tread rubber's E (Pa) and ν at the contact's time scale, which the road's fine texture
  // meets ([rolling] contact_law = "texture"): the two-layer tyre's tread layer, the plate's
  // [tyre.tread] youngs_modulus and poisson_ratio. 0: not given.
  double tread_youngs_modulus = 0.0;
  double tread_poisson_ratio = 0.0;
  // The belt's membrane tension, bending stiffness along the circumference and foundation: the
  // radiating body's deflected shape beyond the patch (tyre_surface_mesh.hpp).
  double belt_tension = 0.0;          // N/m
  double belt_bending = 0.0;          // N·m
  double foundation_stiffness = 0.0;  // N/m³
  // Models that include their tread: the static compliance between the contact cells of the
  // modes beyond the table (static_residual.hpp), for a window of `window` cells of length dx
  // along x and lateral cells centred at y (from the edge of the lateral shapes' span), dy
  // wide (p = i + Nw·j). Empty for the plate, whose tread is separate.
  std::function<Eigen::MatrixXd(int window, double dx, std::span<const double> y, double dy)> residual;
  // Fitted models: the table's origin and the fit's accuracy.
  bool table_from_cache = false;
  bool fits_from_cache = false;
  double table_seconds = 0.0;
  std::optional<ModalFitReport> fit;
};

// The [tyre] table read and checked, before anything is computed from it: a case's other tables
// are checked against it (the radius and width) before the two-layer tyre's table and fits, which
// take tens of seconds without the cache, so that a wrong key anywhere costs no wait.
struct RollingTyreSpec {
  std::string model;  // "plate" | "two_layer" | "tabulated"
  double radius = 0.0;
  double width = 0.0;
  double tread_width = 0.0;  // the width that meets the road (RollingTyreModel::tread_width)
  std::optional<PlateTyre> plate;
  std::shared_ptr<const TwoLayerParameters> two_layer;  // (held by pointer: its header is heavy)
  std::optional<ModalReceptanceTable> table;  // tabulated: the file's table
  // tabulated: the local compliance of the contact cells that the table's modes lack
  // ([tyre.tread], required for rolling).
  std::optional<TreadSettings> tread;
};

// Reads the [tyre] table (or a model file's top level) of model plate, two_layer or tabulated.
// Unknown keys, non-physical values, a [tyre.tread] given to the two-layer model (which includes
// its tread) and a tabulated model without one are InputErrors naming the file and the key.
RollingTyreSpec read_rolling_tyre_spec(const ConfigTable& tyre);

// The rolling model of a checked table. `cache_directory`: where two-layer tables and fits are
// kept between runs (none: not cached).
RollingTyreModel make_rolling_tyre_model(RollingTyreSpec spec, const std::optional<std::filesystem::path>& cache_directory);

}  // namespace rollnoise
