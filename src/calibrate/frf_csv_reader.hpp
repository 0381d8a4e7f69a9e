#pragma once
// Measured FRFs as CSV: one FRF per file, in one of two forms
//
//   frequency_hz,re,im                 (real and imaginary part)
//   frequency_hz,magnitude,phase_deg   (magnitude >= 0, phase in degrees)
//
// The frequency column may also be frequency_khz or angular_frequency_rad_s. Lines starting
// with '#' are comments; comment lines of the form `# key = value` with these keys describe
// the measurement (other comment lines are free text):
//
//   data_type    = receptance | mobility | accelerance  (default: the --data-type option)
//   response_x   = 0.1    response_y   = 0.09             (m, tyre models: where the response
//   excitation_x = 0.0    excitation_y = 0.09              was measured and the force applied)
//
// Values are in SI units (m, s, N) in the model's sign convention: positive when the response
// moves along the force. The reader survives arbitrary bytes: anything malformed is an
// InputError naming the file and line.
#include <filesystem>
#include <string>
#include <vector>

#include "calibrate/measured_frf.hpp"

namespace rollnoise {

struct FrfReadOptions {
  FrfQuantity quantity = FrfQuantity::mobility;  // what the data is when the file does not say
  // The quantity was given explicitly (--data-type): a file that says otherwise is an error.
  bool quantity_given = false;
};

struct FrfFile {
  std::vector<MeasuredFrf> frfs;
  std::vector<std::string> notes;  // what was left out or assumed, for the user
};

// Parses CSV text; `source` names it in messages.
FrfFile parse_frf_csv(const std::string& text, const std::string& source, const FrfReadOptions& options);
FrfFile read_frf_csv(const std::filesystem::path& path, const FrfReadOptions& options);

}  // namespace rollnoise
