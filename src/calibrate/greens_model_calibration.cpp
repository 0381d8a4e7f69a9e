#include "calibrate/greens_model_calibration.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/config_table.hpp"
#include "core/error.hpp"
#include "greens/model_factory.hpp"

namespace rollnoise {
namespace {

std::unique_ptr<GreensModel> build(const toml::table& model, const std::string& source) {
  return make_greens_model(ConfigTable(model, source, ""));
}

class GreensModelReceptance : public ReceptanceFunction {
 public:
  GreensModelReceptance(const toml::table& model, std::string source, std::vector<FitParameter> parameters,
                        Eigen::Index response, Eigen::Index excitation)
      : model_(model),
        source_(std::move(source)),
        parameters_(std::move(parameters)),
        response_(response),
        excitation_(excitation) {}

  std::complex<double> evaluate(std::span<const double> values, double omega, std::complex<double>* gradient,
                                std::span<const std::size_t> wanted) const override {
    toml::table trial = model_;
    for (std::size_t k = 0; k < parameters_.size(); ++k) trial.insert_or_assign(parameters_[k].name, values[k]);
    const std::complex<double> alpha = build(trial, source_)->receptance(omega)(response_, excitation_);
    if (gradient != nullptr && !wanted.empty())
      central_difference_gradient(*this, parameters_, values, omega, gradient, wanted);
    return alpha;
  }

 private:
  toml::table model_;
  std::string source_;
  std::vector<FitParameter> parameters_;
  Eigen::Index response_;
  Eigen::Index excitation_;
};

}  // namespace

GreensModelCalibration::GreensModelCalibration(toml::table model, std::string source)
    : model_(std::move(model)), source_(std::move(source)) {
  const std::unique_ptr<GreensModel> built = build(model_, source_);
  name_ = built->name();
  offsets_ = built->contact_point_offsets();
  for (const auto& [key, node] : model_) {
    if (!node.is_floating_point()) continue;
    const double value = *node.value<double>();
    if (value > 0.0 && std::isfinite(value)) parameters_.push_back(log_parameter(std::string(key.str()), "", value));
  }
}

std::vector<std::string> GreensModelCalibration::default_free_parameters() const {
  std::vector<std::string> names;
  for (const auto& p : parameters_) names.push_back(p.name);
  return names;
}

std::unique_ptr<ReceptanceFunction> GreensModelCalibration::receptance(const FrfPoints& points) const {
  const auto point_of = [&](const BeltPosition& position, const char* what) {
    for (std::size_t i = 0; i < offsets_.size(); ++i)
      if (std::abs(position.x - offsets_[i]) <= 1e-9 + 1e-6 * std::abs(offsets_[i]))
        return static_cast<Eigen::Index>(i);
    std::ostringstream problem;
    problem << "the " << what << " position x = " << position.x << " m is not a contact point of the " << name_
            << " model; its points are at x =";
    for (double x : offsets_) problem << ' ' << x;
    problem << " m";
    throw InputError("", "", problem.str());
  };
  return std::make_unique<GreensModelReceptance>(model_, source_, parameters_, point_of(points.response, "response"),
                                                 point_of(points.excitation, "excitation"));
}

double GreensModelCalibration::highest_frequency_hz() const { return std::numeric_limits<double>::infinity(); }

}  // namespace rollnoise
