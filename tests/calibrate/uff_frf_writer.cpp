#include "calibrate/uff_frf_writer.hpp"

#include <bit>
#include <cstdio>
#include <cstring>

namespace rollnoise::testing {
namespace {

std::string format(const char* pattern, auto... values) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, values...);
  return buffer;
}

std::string padded(const std::string& text) {
  std::string line = text;
  line.resize(80, ' ');
  return line + "\n";
}

std::string axis(int type, const std::string& label, const std::string& units, int length, int force) {
  return format("%10d%5d%5d%5d %-20s %-20s\n", type, length, force, 0, label.c_str(), units.c_str());
}

template <typename T>
void append_binary(std::string& out, T value, bool little_endian) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (little_endian != (std::endian::native == std::endian::little))
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  out.append(bytes, sizeof(T));
}

}  // namespace

std::string uff58_text(const std::vector<UffFrfRecord>& records, const UffWriteOptions& options) {
  std::string out;
  for (const UffFrfRecord& r : records) {
    const std::size_t n = r.frequency_hz.size();
    const int ordinate = r.complex_data ? (options.double_precision ? 6 : 5) : (options.double_precision ? 4 : 2);
    const std::size_t per = (r.complex_data ? 2U : 1U) + (r.even ? 0U : 1U);
    const std::size_t size = options.double_precision ? 8 : 4;
    out += "    -1\n";
    if (options.binary)
      out += format("%6s%6d%6d%12d%12zu%6d%6d%12d%12d\n", "58b", options.little_endian ? 1 : 2, 2, 11, n * per * size, 0,
                    0, 0, 0);
    else
      out += "    58\n";
    out += padded(r.description);
    out += padded("NONE");
    out += padded("01-Jan-24 00:00:00");
    out += padded("rollnoise synthetic test data");
    out += padded("NONE");
    out += format("%5d%10d%5d%10d %-10s%10lld%4d %-10s%10lld%4d\n", r.function_type, 1, 0, 0, "TYRE",
                  static_cast<long long>(r.response_node), r.response_direction, "TYRE",
                  static_cast<long long>(r.reference_node), r.reference_direction);
    const double first = r.even ? r.frequency_hz.front() : 0.0;
    const double step = r.even && n > 1 ? r.frequency_hz[1] - r.frequency_hz[0] : 0.0;
    out += format("%10d%10zu%10d%13.5E%13.5E%13.5E\n", ordinate, n, r.even ? 1 : 0, first, step, 0.0);
    out += axis(r.abscissa_type, "Frequency", r.abscissa_units, 0, 0);
    out += axis(r.numerator_type, r.numerator_label, r.numerator_units, 1, 0);
    out += axis(r.denominator_type, "Force", r.denominator_units, 0, 1);
    out += axis(0, "NONE", "NONE", 0, 0);
    std::vector<double> values;
    for (std::size_t k = 0; k < n; ++k) {
      if (!r.even) values.push_back(r.frequency_hz[k]);
      values.push_back(r.values[k].real());
      if (r.complex_data) values.push_back(r.values[k].imag());
    }
    if (options.binary) {
      for (double v : values) {
        if (options.double_precision)
          append_binary(out, v, options.little_endian);
        else
          append_binary(out, static_cast<float>(v), options.little_endian);
      }
      out += "\n";
    } else {
      // 4E20.12 for double, 6E13.5 for single precision (uneven data: the same, the abscissa
      // takes one field of each point).
      const std::size_t per_line = options.double_precision ? 4 : 6;
      const char* field = options.double_precision ? "%20.12E" : "%13.5E";
      for (std::size_t i = 0; i < values.size(); ++i) {
        out += format(field, values[i]);
        if ((i + 1) % per_line == 0 || i + 1 == values.size()) out += "\n";
      }
    }
    out += "    -1\n";
  }
  return out;
}

}  // namespace rollnoise::testing
