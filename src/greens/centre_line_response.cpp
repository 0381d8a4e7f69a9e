#include "greens/centre_line_response.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/config_table.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/model_factory.hpp"
#include "greens/plate_factory.hpp"
#include "greens/two_layer_factory.hpp"
#include "greens/two_layer_greens_functions.hpp"
#include "greens/two_layer_tyre.hpp"

namespace rollnoise {
namespace {

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
      : tyre_(parameters), cell_length_(tyre_.circumference() / 512.0) {}

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
    return {wrapped, 0.5 * tyre_.width(), cell_length_, 0.007};
  }

  TwoLayerTyre tyre_;
  double cell_length_;
  mutable std::unique_ptr<SurfaceResponse> last_;
  mutable double last_omega_ = 0.0;
};

}  // namespace

std::unique_ptr<CentreLineResponse> make_centre_line_response(const ConfigTable& model) {
  const std::string kind = model.choice("model", {"sdof", "coupled_sdof", "plate", "two_layer"});
  if (kind == "plate") return make_plate_centre_line(read_plate_tyre(model).plate);
  if (kind == "two_layer") return std::make_unique<TwoLayerCentreLine>(read_two_layer_tyre(model));
  return std::make_unique<PointModelCentreLine>(make_greens_model(model));
}

std::unique_ptr<CentreLineResponse> make_plate_centre_line(const PlateParameters& plate) {
  return std::make_unique<PlateCentreLine>(plate);
}

}  // namespace rollnoise
