#include "road/line_cleaning.hpp"

#include <stdexcept>

#include "core/error.hpp"
#include "road/profile_cleaning.hpp"

namespace rollnoise {

LineCleaning clean_measured_line(std::vector<double>& z, double spacing_m, const std::string& source) {
  if (!(spacing_m > 0.0)) throw std::invalid_argument("clean_measured_line: spacing must be > 0");
  try {
    const CleaningReport report = clean_profile(z, spacing_m);
    return {report.dropouts, report.spikes};
  } catch (const InputError& e) {
    // clean_profile does not know where the line came from.
    if (e.key() == "profile") {
      throw InputError(source, "", "a height line has no valid value (every sample is a dropout or a spike)");
    }
    throw e.with_source(source);
  }
}

}  // namespace rollnoise
