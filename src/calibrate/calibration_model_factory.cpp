#include "calibrate/calibration_model_factory.hpp"

#include "calibrate/greens_model_calibration.hpp"
#include "calibrate/plate_calibration.hpp"
#include "calibrate/sdof_calibration.hpp"
#include "calibrate/two_layer_calibration.hpp"
#include "core/case_file.hpp"
#include "greens/model_factory.hpp"
#include "greens/plate_factory.hpp"
#include "greens/sdof_model.hpp"
#include "greens/two_layer_factory.hpp"

namespace rollnoise {

std::unique_ptr<CalibrationModel> make_calibration_model(const CaseFile& model_file, double band_top_hz) {
  const ConfigTable top = model_file.top();
  if (!top.contains("model") && model_file.has_section("tyre"))
    top.fail("tyre",
             "calibrate takes a model file (the keys of a [tyre] table at the top level, such as "
             "models/tyres/*.toml), not a case file: calibrate the model file its [tyre] table names, or move the "
             "[tyre] keys to a file of their own");
  if (!top.contains("model"))
    top.fail("model", "is required: \"sdof\", \"coupled_sdof\", \"plate\", \"two_layer\" (or another model of a [tyre] table)");
  const std::string model = top.text("model");
  if (model == "plate") return std::make_unique<PlateCalibration>(read_plate_tyre(top).plate);
  if (model == "two_layer") return std::make_unique<TwoLayerCalibration>(read_two_layer_tyre(top), band_top_hz);
  const std::unique_ptr<GreensModel> built = make_greens_model(top);
  if (const auto* sdof = dynamic_cast<const SdofModel*>(built.get())) {
    const bool coupled = sdof->point_count() == 2;
    const double coupling = coupled ? sdof->coupling_matrix()(0, 1) : 0.0;
    const double spacing = coupled ? sdof->contact_point_offsets()[1] : 0.0;
    return std::make_unique<SdofCalibration>(sdof->parameters(), coupled, coupling, spacing);
  }
  return std::make_unique<GreensModelCalibration>(model_file.root(), model_file.name());
}

}  // namespace rollnoise
