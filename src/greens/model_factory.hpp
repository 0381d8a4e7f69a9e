#pragma once
// Builds a Green's-function model from a [tyre] table (or a model file's top level).
#include <memory>

#include "greens/greens_model.hpp"

namespace rollnoise {

class ConfigTable;

// `model` selects the type; each type reads its own keys, and unknown keys are rejected.
std::unique_ptr<GreensModel> make_greens_model(const ConfigTable& tyre);

class SurfaceReceptanceModel;

// The tyre models known by their receptance between surface points at any frequency, the static
// case included (surface_receptance_model.hpp): model = "two_layer". A layered, modal tyre does
// not fit GreensModel (it has no closed-form g(t) and no fixed set of points); the rolling path
// consumes this interface instead. Unknown keys are rejected.
std::unique_ptr<SurfaceReceptanceModel> make_surface_receptance_model(const ConfigTable& tyre);

}  // namespace rollnoise
