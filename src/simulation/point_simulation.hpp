#pragma once
// A point-model case ([tyre] model = "sdof" or "coupled_sdof"): contact only, no radiation;
// called through run_case (case_run.hpp).
#include <chrono>
#include <filesystem>

#include "simulation/case_run.hpp"

namespace rollnoise {

class CaseFile;

CaseResult run_point_simulation(const CaseFile& file, const std::filesystem::path& out,
                                std::chrono::steady_clock::time_point started, const CaseRunOptions& options);

}  // namespace rollnoise
