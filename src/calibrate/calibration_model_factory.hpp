#pragma once
// The calibration view of a model file (ARCHITECTURE.md: a model file holds the keys of a
// [tyre] table): sdof and coupled_sdof with automatic derivatives, plate with analytic ones,
// two_layer through its layer solutions (two_layer_calibration.hpp), and any other model the
// Green's-function factory builds through its receptance alone.
#include <limits>
#include <memory>

#include "calibrate/calibration_model.hpp"

namespace rollnoise {

class CaseFile;

// Reads and validates the model with the same readers `simulate` uses (unknown keys and
// unphysical values are InputErrors naming the file and key). `band_top_hz`: the highest
// frequency to be fitted (--frequency-range); the two-layer tyre chooses its modes for it
// (+infinity: its default band), the other models ignore it.
std::unique_ptr<CalibrationModel> make_calibration_model(
    const CaseFile& model_file, double band_top_hz = std::numeric_limits<double>::infinity());

}  // namespace rollnoise
