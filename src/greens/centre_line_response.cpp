#include "greens/centre_line_response.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "core/config_table.hpp"
#include "core/error.hpp"
#include "greens/fitted_modal_tyre.hpp"
#include "greens/fitted_modes_cache.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/modal_table_cache.hpp"
#include "greens/model_factory.hpp"
#include "greens/plate_factory.hpp"
#include "greens/sinc.hpp"
#include "greens/tabulated_factory.hpp"
#include "greens/two_layer_factory.hpp"
#include "greens/two_layer_greens_functions.hpp"
#include "greens/two_layer_tyre.hpp"

namespace rollnoise {
namespace {

// The cell over which a force on a tread surface is spread and its response averaged: one of
// the paper's contact grid, L/512 along the circumference and 7 mm across.
constexpr int kCellsAround = 512;
constexpr double kCellWidth = 0.007;

void check_table(double dt, int count) {
  if (!(dt > 0.0) || !std::isfinite(dt) || count < 1) throw std::invalid_argument("green_table: dt > 0 and count >= 1");
}

// The plate: the belt's own response at mid-width (KroppPlate's modal sums). The tread's local
// compliance belongs to the contact grid's cells (tread_compliance.hpp), so it is not included.
class PlateCentreLine final : public CentreLineResponse {
 public:
  explicit PlateCentreLine(const PlateParameters& parameters) : plate_(parameters) {}

  std::string model() const override { return "plate"; }
  std::string description() const override {
    return "the belt (Kropp plate) at mid-width, point values; the tread's local compliance is added per contact "
           "cell by the contact stage and is not included";
  }
  double circumference() const override { return plate_.circumference(); }
  std::vector<double> default_distances() const override { return {0.0, 0.05, 0.1, 0.2, 0.5}; }
  // The highest order's natural frequency bounds what the truncated modal sum describes.
  double default_top_frequency_hz() const override {
    const int m = plate_.parameters().circumferential_modes;
    return std::min(5000.0, plate_.natural_frequency(m, 1) / (2.0 * std::numbers::pi));
  }
  bool has_point(double) const override { return true; }
  std::complex<double> receptance(double distance, double omega) const override {
    const double y = 0.5 * plate_.parameters().width;
    if (omega == 0.0) return plate_.static_compliance(distance, y, y);
    return plate_.receptance(distance, y, y, omega);
  }
  Eigen::MatrixXd green_table(std::span<const double> distances, double dt, int count) const override {
    check_table(dt, count);
    const double y = 0.5 * plate_.parameters().width;
    Eigen::MatrixXd table(count, static_cast<Eigen::Index>(distances.size()));
    std::vector<double> row(distances.size());
    for (int k = 0; k < count; ++k) {
      plate_.green_along(distances, y, y, (k + 1) * dt, row);
      for (std::size_t j = 0; j < row.size(); ++j) table(k, static_cast<Eigen::Index>(j)) = row[j];
    }
    return table;
  }

 private:
  KroppPlate plate_;
};

// The paper's point models (sdof, coupled_sdof): the points are the model's contact points.
class PointModelCentreLine final : public CentreLineResponse {
 public:
  explicit PointModelCentreLine(std::unique_ptr<GreensModel> model)
      : model_(std::move(model)), offsets_(model_->contact_point_offsets()) {}

  std::string model() const override { return model_->name(); }
  std::string description() const override {
    return "the model's contact points, contact spring included in the receptance (its instantaneous part 1/s)";
  }
  double circumference() const override { return 0.0; }
  std::vector<double> default_distances() const override { return offsets_; }
  // Ten times the fastest rate of the model covers its resonances with room to spare.
  double default_top_frequency_hz() const override {
    return std::ceil(10.0 * model_->fastest_rate() / (2.0 * std::numbers::pi));
  }
  bool has_point(double distance) const override { return index(distance) >= 0; }
  std::complex<double> receptance(double distance, double omega) const override {
    const Eigen::Index j = checked(distance);
    if (omega == 0.0) return model_->static_compliance()(0, j);
    return model_->receptance(omega)(0, j);
  }
  Eigen::MatrixXd green_table(std::span<const double> distances, double dt, int count) const override {
    check_table(dt, count);
    Eigen::MatrixXd table(count, static_cast<Eigen::Index>(distances.size()));
    for (int k = 0; k < count; ++k) {
      const Eigen::MatrixXd g = model_->smooth_response((k + 1) * dt);
      for (std::size_t j = 0; j < distances.size(); ++j)
        table(k, static_cast<Eigen::Index>(j)) = g(0, checked(distances[j]));
    }
    return table;
  }

 private:
  Eigen::Index index(double distance) const {
    for (std::size_t i = 0; i < offsets_.size(); ++i)
      if (std::abs(distance - offsets_[i]) <= 1e-9 + 1e-6 * std::abs(offsets_[i])) return static_cast<Eigen::Index>(i);
    return -1;
  }
  Eigen::Index checked(double distance) const {
    const Eigen::Index j = index(distance);
    if (j < 0) throw std::invalid_argument("the point model has no point at this distance");
    return j;
  }

  std::unique_ptr<GreensModel> model_;
  std::vector<double> offsets_;
};

// The two-layer tyre at the tread surface, mid-width. On the tread the point-to-point receptance
// diverges like 1/r (Boussinesq), so force and response are spread over a cell of the paper's
// contact grid (L/512 along, 7 mm across: surface_receptance_model.hpp), local deformation
// included.
class TwoLayerCentreLine final : public CentreLineResponse {
 public:
  explicit TwoLayerCentreLine(const TwoLayerParameters& parameters)
      : tyre_(parameters), cell_length_(tyre_.circumference() / kCellsAround) {}

  std::string model() const override { return "two_layer"; }
  std::string description() const override {
    return "the tread surface at mid-width, force and response averaged over a cell of L/512 x 7 mm, local "
           "deformation included; the time domain holds step means (two_layer_greens_functions.hpp)";
  }
  double circumference() const override { return tyre_.circumference(); }
  std::vector<double> default_distances() const override { return {0.0, 0.05, 0.1, 0.2, 0.5}; }
  double default_top_frequency_hz() const override { return 5000.0; }
  bool has_point(double) const override { return true; }
  std::complex<double> receptance(double distance, double omega) const override {
    // One modal table per frequency serves every distance: keep the last one.
    if (!last_ || last_omega_ != omega) {
      last_ = tyre_.at(omega);
      last_omega_ = omega;
    }
    return last_->receptance(cell(distance), cell(0.0));
  }
  // Every mode the view sums (m = 0 … M), so that a tabulated model of this table sums the same.
  std::optional<ModalReceptanceTable> modal_table(const Eigen::VectorXd& frequency_hz,
                                                  const std::optional<std::filesystem::path>& cache) const override {
    return cached_two_layer_table(tyre_, frequency_hz, tyre_.parameters().circumferential_modes, cache);
  }
  Eigen::MatrixXd green_table(std::span<const double> distances, double dt, int count) const override {
    check_table(dt, count);
    // A centred record of K = 2·(count + 1) samples, t_i = (i − count − 1)·dt: sample
    // i = count + 2 + k is t = (k + 1)·dt.
    const TwoLayerGreensFunctions functions(tyre_, dt, 2 * (count + 1));
    Eigen::MatrixXd table(count, static_cast<Eigen::Index>(distances.size()));
    for (std::size_t j = 0; j < distances.size(); ++j) {
      const std::vector<double> g = functions.between(cell(distances[j]), cell(0.0));
      for (int k = 0; k < count; ++k) table(k, static_cast<Eigen::Index>(j)) = g[static_cast<std::size_t>(count + 2 + k)];
    }
    return table;
  }

 private:
  SurfaceLocation cell(double x) const {
    const double wrapped = x - tyre_.circumference() * std::floor(x / tyre_.circumference());
    return {wrapped, 0.5 * tyre_.width(), cell_length_, kCellWidth};
  }

  TwoLayerTyre tyre_;
  double cell_length_;
  mutable std::unique_ptr<SurfaceResponse> last_;
  mutable double last_omega_ = 0.0;
};

// A tabulated model (a table of modal compliances from a file: modal_table_hdf5.hpp) at its
// surface, mid-width. The table is sampled at fixed frequencies, so every value comes from the
// pole–residue fit of each mode that rolling uses too (fitted_modal_tyre.hpp): H_mn at any ω,
// and the step means of h_mn in closed form. Force and response are spread over the two-layer
// view's cell (L/512 × 7 mm): a table of a tread surface has the same diverging point response,
// and a table written from a two_layer model then gives that model's receptance.
class TabulatedCentreLine final : public CentreLineResponse {
 public:
  TabulatedCentreLine(ModalReceptanceTable table, const std::optional<std::filesystem::path>& cache)
      : fitted_(fit(std::move(table), cache)) {
    const ModalReceptanceTable& t = fitted_.table();
    const double cell_length = t.circumference() / kCellsAround;
    const double cell_width = std::min(kCellWidth, t.width);  // a cell inside even a narrow strip
    // Per mode the cells' means squared, the lateral shape at mid-width squared and the modal
    // norm: α = Σ_m w_m cos(k_m d)·c_m² Σ_n φ_n(b/2)²·c_n²·H_mn/(L·N_n), w_0 = 1, w_m = 2.
    circumferential_.resize(static_cast<std::size_t>(t.orders + 1));
    for (int m = 0; m <= t.orders; ++m) {
      const double c = sinc(0.5 * t.wavenumber_x(m) * cell_length);
      circumferential_[static_cast<std::size_t>(m)] = (m == 0 ? 1.0 : 2.0) * c * c;
    }
    lateral_.resize(static_cast<std::size_t>(t.lateral_orders));
    for (int l = 0; l < t.lateral_orders; ++l) {
      const int n = t.first_lateral_order + l;
      const double shape = t.lateral_shape_value(n, 0.5 * t.width) * sinc(0.5 * t.wavenumber_y(n) * cell_width);
      // sin(nπ/2) of an even n is zero up to rounding: such modes do not move the centre line.
      lateral_[static_cast<std::size_t>(l)] = std::abs(shape) < 1e-12 ? 0.0 : shape * shape / t.modal_norm(n);
    }
    std::ostringstream text;
    text << "the surface at mid-width of the tabulated table " << t.source << " (" << t.lateral_orders
         << " lateral x " << t.orders + 1 << " orders, " << t.frequency.size()
         << " frequencies), force and response averaged over a cell of L/512 x " << cell_width * 1e3
         << " mm as for two_layer; every value from the pole-residue fit of each mode (fitted_modal_tyre.hpp), "
            "the time domain as the fit's step means in closed form";
    description_ = text.str();
  }

  std::string model() const override { return "tabulated"; }
  std::string description() const override { return description_; }
  double circumference() const override { return fitted_.circumference(); }
  std::vector<double> default_distances() const override { return {0.0, 0.05, 0.1, 0.2, 0.5}; }
  // Beyond its highest frequency the table says nothing: the fit there is an extrapolation.
  double default_top_frequency_hz() const override {
    const Eigen::VectorXd& f = fitted_.table().frequency;
    return std::min(5000.0, f(f.size() - 1));
  }
  bool has_point(double) const override { return true; }
  std::complex<double> receptance(double distance, double omega) const override {
    const ModalReceptanceTable& t = fitted_.table();
    // The lateral sum per order serves every distance at this ω: keep the last one.
    if (per_order_.empty() || last_omega_ != omega) {
      per_order_.assign(circumferential_.size(), 0.0);
      for (int l = 0; l < t.lateral_orders; ++l) {
        const double lateral = lateral_[static_cast<std::size_t>(l)];
        if (lateral == 0.0) continue;
        for (int m = 0; m <= t.orders; ++m)
          per_order_[static_cast<std::size_t>(m)] += lateral * fitted_.fitted(m, l).receptance(omega);
      }
      last_omega_ = omega;
    }
    std::complex<double> sum = 0.0;
    for (int m = 0; m <= t.orders; ++m) {
      const auto i = static_cast<std::size_t>(m);
      sum += circumferential_[i] * std::cos(t.wavenumber_x(m) * distance) * per_order_[i];
    }
    return sum;
  }
  Eigen::MatrixXd green_table(std::span<const double> distances, double dt, int count) const override {
    check_table(dt, count);
    const ModalReceptanceTable& t = fitted_.table();
    const auto orders = static_cast<Eigen::Index>(t.orders + 1);
    // The step means (1/dt)∫_{k·dt}^{(k+1)·dt} h_mn, summed over the lateral orders per order m.
    Eigen::MatrixXd per_order = Eigen::MatrixXd::Zero(count, orders);
    for (int l = 0; l < t.lateral_orders; ++l) {
      const double lateral = lateral_[static_cast<std::size_t>(l)];
      if (lateral == 0.0) continue;
      for (int m = 0; m <= t.orders; ++m) {
        const PoleResidueResponse& h = fitted_.fitted(m, l);
        for (int k = 0; k < count; ++k) {
          // The first step's integral includes the δ part (direct), which the table leaves out.
          double integral = h.phase_integral(0.0, k * dt, (k + 1) * dt).real();
          if (k == 0) integral -= h.direct;
          per_order(k, m) += lateral * integral / dt;
        }
      }
    }
    Eigen::MatrixXd along(orders, static_cast<Eigen::Index>(distances.size()));
    for (Eigen::Index m = 0; m < orders; ++m)
      for (std::size_t j = 0; j < distances.size(); ++j)
        along(m, static_cast<Eigen::Index>(j)) = circumferential_[static_cast<std::size_t>(m)] *
                                                 std::cos(t.wavenumber_x(static_cast<int>(m)) * distances[j]);
    return per_order * along;
  }
  const FittedModalTyre* fitted_modes() const override { return &fitted_; }

 private:
  // A table that passes validation may still defeat the fit (a mode that is zero somewhere,
  // too few frequencies): that is a fault of the file, named as such.
  static FittedModalTyre fit(ModalReceptanceTable table, const std::optional<std::filesystem::path>& cache) {
    const std::string source = table.source;
    try {
      // Its fits through the cache, keyed by the table's content (fitted_modes_cache.hpp).
      const std::string key = fitted_modes_key(modal_table_content_key(table), tyre_mode_fit_options());
      bool from_cache = false;
      return fit_with_cache(std::move(table), "tabulated", cache, key, from_cache);
    } catch (const std::invalid_argument& error) {
      throw InputError(source, "", std::string("its modes cannot be fitted with poles: ") + error.what());
    }
  }

  FittedModalTyre fitted_;
  std::vector<double> circumferential_;  // per m: w_m·c_m²
  std::vector<double> lateral_;          // per l: φ_n(b/2)²·c_n²/(L·N_n)
  std::string description_;
  mutable std::vector<std::complex<double>> per_order_;
  mutable double last_omega_ = 0.0;
};

}  // namespace

std::unique_ptr<CentreLineResponse> make_centre_line_response(const ConfigTable& model) {
  return make_centre_line_response(model, default_cache_directory());
}

std::unique_ptr<CentreLineResponse> make_centre_line_response(const ConfigTable& model,
                                                              const std::optional<std::filesystem::path>& cache) {
  const std::string kind = model.choice("model", {"sdof", "coupled_sdof", "plate", "two_layer", "tabulated"});
  if (kind == "plate") return make_plate_centre_line(read_plate_tyre(model).plate);
  if (kind == "two_layer") return std::make_unique<TwoLayerCentreLine>(read_two_layer_tyre(model));
  if (kind == "tabulated") return std::make_unique<TabulatedCentreLine>(read_tabulated_tyre(model), cache);
  return std::make_unique<PointModelCentreLine>(make_greens_model(model));
}

std::unique_ptr<CentreLineResponse> make_plate_centre_line(const PlateParameters& plate) {
  return std::make_unique<PlateCentreLine>(plate);
}

}  // namespace rollnoise
