#pragma once
// Builds a Green's-function model from a [tyre] table (or a model file's top level).
#include <memory>

#include "greens/greens_model.hpp"

namespace rollnoise {

class ConfigTable;

// `model` selects the type; each type reads its own keys, and unknown keys are rejected.
std::unique_ptr<GreensModel> make_greens_model(const ConfigTable& tyre);

}  // namespace rollnoise
