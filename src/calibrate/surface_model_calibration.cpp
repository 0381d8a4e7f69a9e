#include "calibrate/surface_model_calibration.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/config_table.hpp"
#include "core/error.hpp"
#include "greens/model_factory.hpp"
#include "greens/surface_receptance_model.hpp"

namespace rollnoise {
namespace {

std::unique_ptr<SurfaceReceptanceModel> build(const toml::table& model, const std::string& source) {
  return make_surface_receptance_model(ConfigTable(model, source, ""));
}

// Geometry and mode counts are not fitted: they are known from the tyre or are numerical.
bool fittable(const std::string& key) {
  for (const char* fixed : {"radius", "width", "belt_thickness", "tread_thickness"})
    if (key == fixed) return false;
  return true;
}

class SurfaceModelReceptance : public ReceptanceFunction {
 public:
  SurfaceModelReceptance(const toml::table& model, std::string source, std::vector<FitParameter> parameters,
                         SurfaceLocation response, SurfaceLocation excitation)
      : model_(model),
        source_(std::move(source)),
        parameters_(std::move(parameters)),
        response_(response),
        excitation_(excitation) {}

  std::complex<double> evaluate(std::span<const double> values, double omega, std::complex<double>* gradient,
                                std::span<const std::size_t> wanted) const override {
    toml::table trial = model_;
    for (std::size_t k = 0; k < parameters_.size(); ++k) trial.insert_or_assign(parameters_[k].name, values[k]);
    const std::complex<double> alpha = build(trial, source_)->at(omega)->receptance(response_, excitation_);
    if (gradient != nullptr && !wanted.empty())
      central_difference_gradient(*this, parameters_, values, omega, gradient, wanted);
    return alpha;
  }

 private:
  toml::table model_;
  std::string source_;
  std::vector<FitParameter> parameters_;
  SurfaceLocation response_;
  SurfaceLocation excitation_;
};

}  // namespace

SurfaceModelCalibration::SurfaceModelCalibration(toml::table model, std::string source)
    : model_(std::move(model)), source_(std::move(source)) {
  const std::unique_ptr<SurfaceReceptanceModel> built = build(model_, source_);
  name_ = built->name();
  circumference_ = built->circumference();
  width_ = built->width();
  for (const auto& [key, node] : model_) {
    if (!node.is_floating_point()) continue;
    const std::string name(key.str());
    const double value = *node.value<double>();
    if (value > 0.0 && std::isfinite(value) && fittable(name)) parameters_.push_back(log_parameter(name, "", value));
  }
  // c_s = √(E/(2(1 + ν)ρ)) of the tread; M orders reach the wavelength L/M.
  const ConfigTable table(model_, source_, "");
  const double shear_speed = std::sqrt(table.positive("tread_youngs_modulus") /
                                       (2.0 * (1.0 + table.positive("tread_poisson_ratio")) *
                                        table.positive("tread_density")));
  const double orders = static_cast<double>(table.integer("circumferential_modes", 0, 0, 1 << 20));
  highest_hz_ = shear_speed * std::max(1.0, orders) / circumference_;
}

std::vector<std::string> SurfaceModelCalibration::default_free_parameters() const {
  std::vector<std::string> names;
  for (const char* key : {"belt_youngs_modulus_x", "belt_youngs_modulus_y", "tension_x", "tension_y",
                          "foundation_stiffness", "tread_youngs_modulus", "belt_loss_factor", "tread_loss_factor",
                          "foundation_loss_factor"})
    if (index_of(key) >= 0) names.emplace_back(key);
  return names;
}

std::unique_ptr<ReceptanceFunction> SurfaceModelCalibration::receptance(const FrfPoints& points) const {
  const auto place = [&](const BeltPosition& p, const char* what) {
    if (!(p.y >= 0.0 && p.y <= width_)) {
      std::ostringstream problem;
      problem << "the " << what << " position y = " << p.y << " m lies outside the belt (0 to " << width_ << " m)";
      throw InputError("", "", problem.str());
    }
    const double x = p.x - circumference_ * std::floor(p.x / circumference_);
    return SurfaceLocation{x, p.y, kTransducerSize, kTransducerSize};
  };
  return std::make_unique<SurfaceModelReceptance>(model_, source_, parameters_, place(points.response, "response"),
                                                  place(points.excitation, "excitation"));
}

}  // namespace rollnoise
