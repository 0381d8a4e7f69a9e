#pragma once
// One measured frequency response function, as the fit uses it: mobility (velocity over force,
// in the model's sign convention: positive when the response moves along the force) at
// frequencies above 0 Hz, in increasing order, with where it was measured.
#include <complex>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "calibrate/frf_quantity.hpp"

namespace rollnoise {

// A point on the tyre belt (MODEL.md §4): x along the circumference, y across the belt from
// one belt edge, both in m. Point models use x only (the contact point offsets along the road).
struct BeltPosition {
  double x = 0.0;
  double y = 0.0;
};

// A UFF node and direction (record 6): direction 0 scalar, ±1..±3 translations X, Y, Z.
struct UffDof {
  std::int64_t node = 0;
  int direction = 0;
};

struct MeasuredFrf {
  std::string source;  // the file
  std::string label;   // which FRF of the file, such as "dataset 2 (line 40)"; empty for CSV
  FrfQuantity quantity = FrfQuantity::mobility;  // as measured, before the conversion
  Eigen::VectorXd frequency_hz;                  // > 0, strictly increasing
  Eigen::VectorXcd mobility;                     // m/(N·s), never 0
  std::optional<BeltPosition> response;
  std::optional<BeltPosition> excitation;
  std::optional<UffDof> response_dof;  // UFF records only
  std::optional<UffDof> reference_dof;

  Eigen::Index size() const { return frequency_hz.size(); }
  // "file" or "file, dataset 2 (line 40)", for messages.
  std::string name() const;
};

// Validates and converts raw values of `quantity` at `frequency_hz` into frf.frequency_hz and
// frf.mobility: frequencies must be >= 0 and strictly increasing and values non-zero;
// points at 0 Hz are left out (a DC value has no phase, and iω = 0 there), with a note in
// `notes`. `where(k)` names point k in messages (such as "line 12"). Throws InputError naming
// frf.source.
void fill_mobility(MeasuredFrf& frf, const std::vector<double>& frequency_hz,
                   const std::vector<std::complex<double>>& values,
                   const std::function<std::string(std::size_t)>& where,
                   std::vector<std::string>& notes);

}  // namespace rollnoise
