#include "greens/centre_line_response.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <numbers>

#include "core/config_table.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/model_factory.hpp"
#include "greens/plate_factory.hpp"

namespace rollnoise {
namespace {

// The plate: the belt's own response at mid-width (KroppPlate's modal sums). The tread's local
// compliance belongs to the contact grid's cells (tread_compliance.hpp), so it is not included.
class PlateCentreLine final : public CentreLineResponse {
 public:
  explicit PlateCentreLine(const PlateParameters& parameters) : plate_(parameters) {}

  std::string model() const override { return "plate"; }
  std::string description() const override {
    return "the belt (Kropp plate) at mid-width; the tread's local compliance is added per contact cell by the "
           "contact stage and is not included";
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
  double green(double distance, double t) const override {
    const double y = 0.5 * plate_.parameters().width;
    return plate_.green(distance, y, y, t);
  }
  void green_along(std::span<const double> distances, double t, std::span<double> out) const override {
    const double y = 0.5 * plate_.parameters().width;
    plate_.green_along(distances, y, y, t, out);
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
    return "the model's contact points, contact spring included (its instantaneous part 1/s)";
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
  double green(double distance, double t) const override { return model_->smooth_response(t)(0, checked(distance)); }

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

}  // namespace

std::unique_ptr<CentreLineResponse> make_centre_line_response(const ConfigTable& model) {
  const std::string kind = model.choice("model", {"sdof", "coupled_sdof", "plate"});
  if (kind == "plate") return make_plate_centre_line(read_plate_tyre(model).plate);
  return std::make_unique<PointModelCentreLine>(make_greens_model(model));
}

}  // namespace rollnoise

namespace rollnoise {

void CentreLineResponse::green_along(std::span<const double> distances, double t, std::span<double> out) const {
  if (distances.size() != out.size()) throw std::invalid_argument("green_along needs one output per distance");
  for (std::size_t i = 0; i < distances.size(); ++i) out[i] = green(distances[i], t);
}

std::unique_ptr<CentreLineResponse> make_plate_centre_line(const PlateParameters& plate) {
  return std::make_unique<PlateCentreLine>(plate);
}

}  // namespace rollnoise
