#pragma once
// Cleaning of one measured height line before use: dropouts (NaN: no reading) and spikes
// handled per ISO 13473-1. The work is done by clean_profile (profile_cleaning.hpp: spikes are
// steps |dz| >= 3 dx between valid samples; dropouts and spikes are filled by linear
// interpolation); this is the one place the readers call it, so that every reader cleans the
// same way and its messages name the file.
#include <cstddef>
#include <string>
#include <vector>

namespace rollnoise {

struct LineCleaning {
  std::size_t dropouts = 0;  // samples that had no value (NaN) and were filled
  std::size_t spikes = 0;    // samples that were spikes and were replaced
};

// Cleans `z` (evenly sampled at `spacing_m` > 0; NaN marks a dropout) in place. Afterwards every
// value is finite. `source` names the data in messages (an InputError when the line cannot be
// cleaned, such as one with no valid value).
LineCleaning clean_measured_line(std::vector<double>& z, double spacing_m, const std::string& source);

}  // namespace rollnoise
