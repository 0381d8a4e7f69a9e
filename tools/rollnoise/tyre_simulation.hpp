#pragma once
// `rollnoise simulate` for a rolling tyre ([tyre] model = "plate").
#include <chrono>
#include <filesystem>

namespace rollnoise {

class CaseFile;

// Runs the case and writes its outputs into `out` (atomically). Returns the exit status.
// A run too large for the machine's memory or disk is refused before it starts unless `force`
// (run_size.hpp).
int run_tyre_simulation(const CaseFile& file, const std::filesystem::path& out,
                        std::chrono::steady_clock::time_point started, bool force = false);

}  // namespace rollnoise
