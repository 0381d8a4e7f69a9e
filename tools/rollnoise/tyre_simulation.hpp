#pragma once
// `rollnoise simulate` for a rolling tyre ([tyre] model = "plate").
#include <chrono>
#include <filesystem>

namespace rollnoise {

class CaseFile;

// Runs the case and writes its outputs into `out` (atomically). Returns the exit status.
int run_tyre_simulation(const CaseFile& file, const std::filesystem::path& out,
                        std::chrono::steady_clock::time_point started);

}  // namespace rollnoise
