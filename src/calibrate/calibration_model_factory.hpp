#pragma once
// The calibration view of a model file (ARCHITECTURE.md: a model file holds the keys of a
// [tyre] table): sdof and coupled_sdof with automatic derivatives, plate with analytic ones,
// and any other model the Green's-function factory builds through its receptance alone.
#include <memory>

#include "calibrate/calibration_model.hpp"

namespace rollnoise {

class CaseFile;

// Reads and validates the model with the same readers `simulate` uses (unknown keys and
// unphysical values are InputErrors naming the file and key).
std::unique_ptr<CalibrationModel> make_calibration_model(const CaseFile& model_file);

}  // namespace rollnoise
