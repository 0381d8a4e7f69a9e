#pragma once
// A rolling tyre case ([tyre] model = "plate", "two_layer" or "tabulated"): contact, response,
// radiation, sound; called through run_case (case_run.hpp).
#include <chrono>
#include <filesystem>

#include "simulation/case_run.hpp"

namespace rollnoise {

class CaseFile;

// Runs the case and writes its outputs into `out` (atomically).
CaseResult run_tyre_simulation(const CaseFile& file, const std::filesystem::path& out,
                               std::chrono::steady_clock::time_point started, const CaseRunOptions& options);

}  // namespace rollnoise
