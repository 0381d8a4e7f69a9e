#include "simulation/case_run.hpp"

#include <chrono>

#include "core/case_file.hpp"
#include "core/error.hpp"
#include "simulation/point_simulation.hpp"
#include "simulation/tyre_simulation.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

fs::path default_case_output(const CaseFile& file) {
  const std::string directory = file.optional_section("output").text("directory", "");
  return !directory.empty() ? fs::path(directory) : fs::path("out") / fs::path(file.path()).stem();
}

CaseResult run_case(const CaseFile& file, const fs::path& out, const CaseRunOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  file.reject_unknown_sections({"tyre", "road", "rolling", "radiation", "output"});
  try {
    const fs::path folder = out.empty() ? default_case_output(file) : out;
    const std::string kind =
        file.section("tyre").choice("model", {"sdof", "coupled_sdof", "plate", "two_layer", "tabulated"});
    if (kind == "sdof" || kind == "coupled_sdof") return run_point_simulation(file, folder, started, options);
    return run_tyre_simulation(file, folder, started, options);
  } catch (const InputError& error) {
    throw error.with_source(file.name());
  }
}

}  // namespace rollnoise
