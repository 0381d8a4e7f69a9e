#pragma once
// Writes FRFs as UFF dataset 58 (ASCII) or 58b (binary) the way measurement systems do, to
// make test vectors and the example files of data/mobility. The reader (core/uff58.hpp) is
// independent of it: a record written here and read back is a real round trip.
#include <complex>
#include <cstdint>
#include <string>
#include <vector>

namespace rollnoise::testing {

struct UffFrfRecord {
  std::string description = "FRF";  // id line 1
  int function_type = 4;            // 4: frequency response function
  std::int64_t response_node = 1;
  int response_direction = 3;  // +Z
  std::int64_t reference_node = 1;
  int reference_direction = 3;
  int abscissa_type = 18;  // frequency
  std::string abscissa_units = "Hz";
  int numerator_type = 11;  // velocity
  std::string numerator_label = "Velocity";
  std::string numerator_units = "m/s";
  int denominator_type = 13;  // excitation force
  std::string denominator_units = "N";
  bool even = true;                   // even abscissa: frequency_hz[k] = first + k·step
  std::vector<double> frequency_hz;   // for even spacing, written as min and increment (E13.5)
  std::vector<std::complex<double>> values;
  bool complex_data = true;  // false: real data (the real parts)
};

struct UffWriteOptions {
  bool binary = false;          // 58b
  bool double_precision = true;
  bool little_endian = true;    // 58b only
};

std::string uff58_text(const std::vector<UffFrfRecord>& records, const UffWriteOptions& options);

}  // namespace rollnoise::testing
