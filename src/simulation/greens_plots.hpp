#pragma once
// The figures of a model's Green's function, shared by `greens` and `simulate`.
#include <filesystem>

#include "core/gnuplot.hpp"

namespace rollnoise {

class CentreLineResponse;

// The paper's Fig. 5a: the Green's function along the circumference for an impulse at the centre
// of the belt, at 0.25, 0.5, 1 and 2 ms, on `points` positions around the tyre
// (greens_circumference.csv, .gp, .png).
// batch: drawn with its other plots (core/gnuplot.hpp); null: at once.
void write_greens_circumference(const std::filesystem::path& dir, const CentreLineResponse& response, int points,
                                PlotBatch* batch = nullptr);

}  // namespace rollnoise
